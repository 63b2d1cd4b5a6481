# Boundary-element Stokes tests (label "stokes"; seed 003 ch. 4-5). Each test prints its
# measured numbers and the reference it is checked against (written next to each test).
pl_add_c_test(test_stokes_kernels SOURCES ${PL_TEST_DIR}/stokes/test_stokes_kernels.c LABEL "stokes;fluid" TIMEOUT 120)
