# Resolved Navier–Stokes (seed 004; fluid/navier_stokes/): kernels without a world, flows on
# fixed gmsh meshes against analytic and published values, the model in a world. Label
# "navier_stokes"; validations over ~20 s also "long" (their fast variants stay unlabelled).
pl_add_c_test(test_ns_kernels SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_kernels.c LABEL "navier_stokes;unit" TIMEOUT 60)
pl_add_c_test(test_ns_flow SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_flow.c LABEL "navier_stokes;physics" TIMEOUT 120)
# Published benchmarks (cavity / Ghia, DFG 2D-1, cylinder between plates): fast meshes here,
# the mesh sequences and all three elements with "long".
pl_add_c_test(test_ns_validation SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_validation.c LABEL "navier_stokes;physics" TIMEOUT 120)
add_test(NAME test_ns_validation_long COMMAND test_ns_validation long)
set_tests_properties(test_ns_validation_long PROPERTIES LABELS "navier_stokes;physics;long" TIMEOUT 900)
pl_add_c_test(test_ns_world SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_world.c LABEL "navier_stokes;physics" TIMEOUT 120)
add_test(NAME test_ns_world_long COMMAND test_ns_world long)
set_tests_properties(test_ns_world_long PROPERTIES LABELS "navier_stokes;physics;long" TIMEOUT 900)
