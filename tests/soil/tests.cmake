# Saturated-soil tests (label "soil"; long ones also "long"). Each prints its measured numbers
# beside the analytic reference written next to the test (docs/soil.md §4).
pl_add_c_test(test_soil_terzaghi SOURCES ${PL_TEST_DIR}/soil/test_soil_terzaghi.c LABEL soil TIMEOUT 60)
pl_add_c_test(test_soil_undrained SOURCES ${PL_TEST_DIR}/soil/test_soil_undrained.c LABEL soil TIMEOUT 120)
pl_add_c_test(test_soil_quicksand SOURCES ${PL_TEST_DIR}/soil/test_soil_quicksand.c LABEL soil TIMEOUT 120)
# The liquefaction scene run whole; its on_finish asserts the r_u criteria (docs/soil.md §5.3).
if(TARGET porelab)
  add_test(NAME soil_liquefaction COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/soil/liquefaction.lua -q
           --fps 30 --size 120x42 --out ${CMAKE_CURRENT_BINARY_DIR}/soil-out/liquefaction)
  set_tests_properties(soil_liquefaction PROPERTIES LABELS "soil;long" TIMEOUT 600)
endif()
# Benchmark (not a test): tests/bench/bench_soil.sh [build/app/porelab] (docs/soil.md §6).
