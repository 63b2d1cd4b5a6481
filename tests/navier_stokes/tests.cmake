# Resolved Navier–Stokes (seed 004; fluid/navier_stokes/): kernels without a world, flows on
# fixed gmsh meshes against analytic and published values, the model in a world. Label
# "navier_stokes"; validations over ~20 s also "long" (their fast variants stay unlabelled).
pl_add_c_test(test_ns_kernels SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_kernels.c LABEL "navier_stokes;unit" TIMEOUT 60)
pl_add_c_test(test_ns_flow SOURCES ${PL_TEST_DIR}/navier_stokes/test_ns_flow.c LABEL "navier_stokes;physics" TIMEOUT 120)
