# Resolved Navier–Stokes (seed 004; fluid/navier_stokes/): kernels without a world, flows on
# fixed gmsh meshes against analytic and published values, the model in a world. Label
# "navier_stokes"; validations over ~20 s also "long" (their fast variants stay unlabelled).
pl_add_c_test(test_ns_kernels SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_kernels.c LABEL "navier_stokes;unit" TIMEOUT 60)
pl_add_c_test(test_ns_flow SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_flow.c LABEL "navier_stokes;physics" TIMEOUT 120)
# Published benchmarks (cavity / Ghia, DFG 2D-1, cylinder between plates): fast meshes here,
# the mesh sequences and all three elements with "long".
# The fast meshes run as three tests (test_ns_validation: the cavity; _dfg; _plates: a few s CPU
# each) so that none passes ~20 s.
add_executable(test_ns_validation ${PL_TEST_DIR}/navier_stokes/test_ns_validation.c)
target_include_directories(test_ns_validation PRIVATE ${PL_TEST_DIR} ${CMAKE_SOURCE_DIR}/engine/src)
target_link_libraries(test_ns_validation PRIVATE porelab_engine)
add_test(NAME test_ns_validation COMMAND test_ns_validation cavity)
foreach(part dfg plates)
  add_test(NAME test_ns_validation_${part} COMMAND test_ns_validation ${part})
endforeach()
set_tests_properties(test_ns_validation test_ns_validation_dfg test_ns_validation_plates PROPERTIES
                     LABELS "navier_stokes;physics" TIMEOUT 120)
add_test(NAME test_ns_validation_long CONFIGURATIONS long COMMAND test_ns_validation long)
set_tests_properties(test_ns_validation_long PROPERTIES LABELS "navier_stokes;physics;long" TIMEOUT 900)
pl_add_c_test(test_ns_world SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_world.c LABEL "navier_stokes;physics" TIMEOUT 120)
add_test(NAME test_ns_world_long CONFIGURATIONS long COMMAND test_ns_world long)
set_tests_properties(test_ns_world_long PROPERTIES LABELS "navier_stokes;physics;long" TIMEOUT 900)
# Benchmark (not a test): error against CPU time for the three elements, cost split, charts
# for docs/navier-stokes.md (with PLplot):  build/tests/bench_navier_stokes docs/figures
add_executable(bench_navier_stokes ${PL_TEST_DIR}/bench/bench_navier_stokes.c)
target_include_directories(bench_navier_stokes PRIVATE ${PL_TEST_DIR} ${CMAKE_SOURCE_DIR}/engine/src)
target_link_libraries(bench_navier_stokes PRIVATE porelab_engine)
if(TARGET porelab_render) # the charts through the app's charts (house style)
  target_sources(bench_navier_stokes PRIVATE ${PL_TEST_DIR}/bench/bench_chart.c)
  target_compile_definitions(bench_navier_stokes PRIVATE BENCH_CHART=1)
  target_include_directories(bench_navier_stokes PRIVATE ${CMAKE_SOURCE_DIR}/app/render)
  target_link_libraries(bench_navier_stokes PRIVATE porelab_render)
endif()
# The granular step (scenes/navier_stokes/granular_step.lua, seed 004 §6.3) run whole, 0.7 s
# after the release (~3.5 min CPU, label long): the grains must come to rest without residual
# noise (the seed: at rest by about 0.35 s): every grain slower than 10 µm/s at the end and the
# kinetic energy below 1e-8 of its peak (measured 1.0 µm/s and 4e-11; at dt = 1e-4 s the grains
# kept a period-two oscillation of about 1 mm/s, docs/navier-stokes.md).
if(TARGET porelab)
  add_test(NAME ns_scene_granular_step_rest CONFIGURATIONS long
           COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/navier_stokes/granular_step.lua -q
                   --param rest_speed=1e-5 --size 16x16 --layers none
                   --out ${CMAKE_CURRENT_BINARY_DIR}/ns-out/granular_step_rest)
  set_tests_properties(ns_scene_granular_step_rest PROPERTIES LABELS "navier_stokes;long" TIMEOUT 1200)
endif()
