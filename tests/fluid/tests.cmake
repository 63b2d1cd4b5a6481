# Fluid tests (label "fluid"; long validations also "long"). Each test prints its measured
# numbers and the reference it is checked against (written next to each test).
pl_add_c_test(test_fluid_mesh SOURCES ${PL_TEST_DIR}/fluid/test_fluid_mesh.c LABEL fluid TIMEOUT 60)
pl_add_c_test(test_fluid_static SOURCES ${PL_TEST_DIR}/fluid/test_fluid_static.c LABEL fluid TIMEOUT 60)
pl_add_c_test(test_fluid_wave SOURCES ${PL_TEST_DIR}/fluid/test_fluid_wave.c LABEL fluid TIMEOUT 60)
target_include_directories(test_fluid_wave PRIVATE ${CHOLMOD_INCLUDE})
pl_add_c_test(test_fluid_buoyancy SOURCES ${PL_TEST_DIR}/fluid/test_fluid_buoyancy.c LABEL fluid TIMEOUT 60)
# Grains pressed into a floor / side wall / corner on the mesh's edge keep rho_f g A (issue 13 item 6)
pl_add_c_test(test_fluid_edge SOURCES ${PL_TEST_DIR}/fluid/test_fluid_edge.c LABEL fluid TIMEOUT 120)
pl_add_c_test(test_fluid_bed SOURCES ${PL_TEST_DIR}/fluid/test_fluid_bed.c LABEL fluid TIMEOUT 120)
pl_add_c_test(test_fluid_porosity SOURCES ${PL_TEST_DIR}/fluid/test_fluid_porosity.c LABEL fluid TIMEOUT 60)
target_include_directories(test_fluid_porosity PRIVATE ${CHOLMOD_INCLUDE})
pl_add_c_test(test_fluid_snapshot SOURCES ${PL_TEST_DIR}/fluid/test_fluid_snapshot.c LABEL fluid TIMEOUT 60)
pl_add_c_test(test_state_file SOURCES ${PL_TEST_DIR}/fluid/test_state_file.c LABEL fluid TIMEOUT 120)
pl_add_c_test(test_fluid_frame SOURCES ${PL_TEST_DIR}/fluid/test_fluid_frame.c LABEL fluid TIMEOUT 60)
# Benchmark (not a test): tests/bench/bench_fluid.c; FreeFEM++ comparison: tests/bench/run_freefem.sh
add_executable(bench_fluid ${PL_TEST_DIR}/bench/bench_fluid.c)
target_link_libraries(bench_fluid PRIVATE porelab_engine)
# Charts for docs/fluid.md (PLplot): build the target fluid_charts and run it with docs/img.
find_library(PLPLOT_LIB plplot)
find_path(PLPLOT_INCLUDE plplot.h PATH_SUFFIXES plplot)
if(PLPLOT_LIB AND PLPLOT_INCLUDE)
  add_executable(fluid_charts EXCLUDE_FROM_ALL ${PL_TEST_DIR}/bench/fluid_charts.c)
  target_include_directories(fluid_charts PRIVATE ${PLPLOT_INCLUDE} ${PL_TEST_DIR})
  target_link_libraries(fluid_charts PRIVATE porelab_engine ${PLPLOT_LIB})
endif()
# Lua binding and scenes: enabled once lua/CMakeLists.txt builds wrap_fluid.c (the lead wires it).
file(READ ${CMAKE_SOURCE_DIR}/lua/CMakeLists.txt _pl_lua_cmake)
string(FIND "${_pl_lua_cmake}" "wrap_fluid.c" _pl_fluid_wired)
if(NOT _pl_fluid_wired EQUAL -1 AND TARGET porelab)
  add_test(NAME fluid_lua_api COMMAND porelab run ${PL_TEST_DIR}/fluid/lua_fluid_api.lua -q
           --out ${CMAKE_CURRENT_BINARY_DIR}/fluid-out/lua_api)
  set_tests_properties(fluid_lua_api PROPERTIES LABELS fluid TIMEOUT 60)
  add_test(NAME fluid_lua_darcy_def COMMAND porelab run ${PL_TEST_DIR}/fluid/lua_darcy_def.lua -q
           --out ${CMAKE_CURRENT_BINARY_DIR}/fluid-out/lua_darcy_def)
  set_tests_properties(fluid_lua_darcy_def PROPERTIES LABELS fluid TIMEOUT 60)
  foreach(scene dam_flow buoyancy prop)
    add_test(NAME fluid_scene_${scene} COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/mimes/${scene}.lua -q
             --steps 40 --every 20 --out ${CMAKE_CURRENT_BINARY_DIR}/fluid-out/${scene})
    set_tests_properties(fluid_scene_${scene} PROPERTIES LABELS fluid TIMEOUT 60)
  endforeach()
  add_test(NAME fluid_scene_quicksand COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/fluid_quicksand.lua -q
           --steps 200 --every 100 --out ${CMAKE_CURRENT_BINARY_DIR}/fluid-out/quicksand)
  set_tests_properties(fluid_scene_quicksand PROPERTIES LABELS fluid TIMEOUT 60)
endif()
# Hydrostatic water (porelab/hydrostatic.h): kernels without a world.
pl_add_c_test(test_hydrostatic_kernels SOURCES ${PL_TEST_DIR}/fluid/test_hydrostatic_kernels.c LABEL fluid TIMEOUT 60)
# Hydrostatic water in a world (floating drafts, the same scene with Darcy, moving level,
# contact force of a sunk pebble) and its Lua binding; benchmark against Darcy (not a test).
pl_add_c_test(test_hydrostatic_world SOURCES ${PL_TEST_DIR}/fluid/test_hydrostatic_world.c LABEL fluid TIMEOUT 120)
add_executable(bench_water ${PL_TEST_DIR}/bench/bench_water.c)
target_link_libraries(bench_water PRIVATE porelab_engine)
if(TARGET porelab)
  add_test(NAME fluid_lua_hydrostatic COMMAND porelab run ${PL_TEST_DIR}/fluid/lua_hydrostatic_api.lua -q
           --out ${CMAKE_CURRENT_BINARY_DIR}/fluid-out/lua_hydrostatic)
  set_tests_properties(fluid_lua_hydrostatic PROPERTIES LABELS fluid TIMEOUT 60)
endif()
