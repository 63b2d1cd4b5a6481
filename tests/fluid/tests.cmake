# Fluid tests (label "fluid"; long validations also "long"). Each test prints its measured
# numbers and the reference it is checked against (written next to each test).
pl_add_c_test(test_fluid_mesh SOURCES ${PL_TEST_DIR}/fluid/test_fluid_mesh.c LABEL fluid TIMEOUT 60)
pl_add_c_test(test_fluid_static SOURCES ${PL_TEST_DIR}/fluid/test_fluid_static.c LABEL fluid TIMEOUT 60)
pl_add_c_test(test_fluid_wave SOURCES ${PL_TEST_DIR}/fluid/test_fluid_wave.c LABEL fluid TIMEOUT 60)
target_include_directories(test_fluid_wave PRIVATE ${CHOLMOD_INCLUDE})
pl_add_c_test(test_fluid_buoyancy SOURCES ${PL_TEST_DIR}/fluid/test_fluid_buoyancy.c LABEL fluid TIMEOUT 60)
pl_add_c_test(test_fluid_bed SOURCES ${PL_TEST_DIR}/fluid/test_fluid_bed.c LABEL fluid TIMEOUT 120)
