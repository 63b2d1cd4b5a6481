# Saturated-soil tests (label "soil"; long ones also "long"). Each prints its measured numbers
# beside the analytic reference written next to the test (docs/soil.md §4).
pl_add_c_test(test_soil_terzaghi SOURCES ${PL_TEST_DIR}/soil/test_soil_terzaghi.c LABEL soil TIMEOUT 60)
pl_add_c_test(test_soil_undrained SOURCES ${PL_TEST_DIR}/soil/test_soil_undrained.c LABEL soil TIMEOUT 120)
