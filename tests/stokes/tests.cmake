# Boundary-element Stokes tests (label "stokes"; seed 003 ch. 4-5). Each test prints its
# measured numbers and the reference it is checked against (written next to each test).
pl_add_c_test(test_stokes_kernels SOURCES ${PL_TEST_DIR}/stokes/test_stokes_kernels.c LABEL "stokes;fluid" TIMEOUT 120)
pl_add_c_test(test_stokes_world SOURCES ${PL_TEST_DIR}/stokes/test_stokes_world.c LABEL "stokes;fluid" TIMEOUT 300)
# Scenes in scenes/stokes/ run a short while without error (porelab, when built).
if(TARGET porelab)
  foreach(scene falling_disc three_discs liquefaction simple_shear)
    add_test(NAME stokes_scene_${scene} COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/stokes/${scene}.lua -q
             --steps 6 --every 3 --out ${CMAKE_CURRENT_BINARY_DIR}/stokes-out/${scene})
    set_tests_properties(stokes_scene_${scene} PROPERTIES LABELS "stokes;fluid" TIMEOUT 120)
  endforeach()
endif()
pl_add_c_test(test_stokes_array SOURCES ${PL_TEST_DIR}/stokes/test_stokes_array.c LABEL "stokes;fluid" TIMEOUT 120)
# The held wall (load_wall) against its closed form, and the artificial gap's effect (the
# table in docs/stokes.md): the same program, second group.
add_test(NAME test_stokes_held COMMAND test_stokes_world held)
set_tests_properties(test_stokes_held PROPERTIES LABELS "stokes;fluid" TIMEOUT 120)
# A chosen container (container = {walls}): the same answer as every wall for one box, a box
# chosen in a world of two, the sheared simple-shear box's closure.
add_test(NAME test_stokes_container COMMAND test_stokes_world container)
set_tests_properties(test_stokes_container PROPERTIES LABELS "stokes;fluid" TIMEOUT 120)
# The Lua API: every bad argument of w:stokes{...} names file, line, argument and range; the
# queries (tests/stokes/lua_api.lua).
if(TARGET porelab)
  add_test(NAME stokes_lua_api COMMAND porelab run ${CMAKE_CURRENT_SOURCE_DIR}/stokes/lua_api.lua -q
           --out ${CMAKE_CURRENT_BINARY_DIR}/stokes-out/lua_api)
  set_tests_properties(stokes_lua_api PROPERTIES LABELS "stokes;fluid" TIMEOUT 60
                       PASS_REGULAR_EXPRESSION "stokes lua api: [0-9]+ checks ok")
endif()
# The §5.1 disc with the hydrostatic and Darcy rungs as the benchmark sets them up: buoyancy
# alone (Archimedes), and the Darcy fluid started from its static field, not from zero pressure.
pl_add_c_test(test_stokes_rungs SOURCES ${PL_TEST_DIR}/stokes/test_stokes_rungs.c LABEL "stokes;fluid" TIMEOUT 60)
# The saturated simple shear of the 20-disc sample (scenes/stokes/simple_shear.lua) sheared to 3 %:
# pore-pressure rise = drop of effective stress of the dry constant-volume twin (Dyvik et al. 1987).
if(TARGET porelab)
  add_test(NAME stokes_simple_shear_short CONFIGURATIONS long COMMAND porelab run ${CMAKE_CURRENT_SOURCE_DIR}/stokes/simple_shear_short.lua
           --trust -q --no-frames --out ${CMAKE_CURRENT_BINARY_DIR}/stokes-out/simple_shear_short)
  set_tests_properties(stokes_simple_shear_short PROPERTIES LABELS "stokes;fluid;long" TIMEOUT 900
                       PASS_REGULAR_EXPRESSION "stokes simple shear short: ok")
endif()
