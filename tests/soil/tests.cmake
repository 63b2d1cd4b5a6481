# Saturated-soil tests (label "soil"; long ones also "long"). Each prints its measured numbers
# beside the analytic reference written next to the test (docs/soil.md §4).
pl_add_c_test(test_soil_terzaghi SOURCES ${PL_TEST_DIR}/soil/test_soil_terzaghi.c LABEL soil TIMEOUT 60)
pl_add_c_test(test_soil_undrained SOURCES ${PL_TEST_DIR}/soil/test_soil_undrained.c LABEL soil TIMEOUT 120)
pl_add_c_test(test_soil_quicksand SOURCES ${PL_TEST_DIR}/soil/test_soil_quicksand.c LABEL soil TIMEOUT 120)
pl_add_c_test(test_soil_overburden SOURCES ${PL_TEST_DIR}/soil/test_soil_overburden.c LABEL soil TIMEOUT 60)
# The liquefaction scene run whole; its on_finish asserts the r_u criteria (docs/soil.md §5.3).
if(TARGET porelab)
  add_test(NAME soil_liquefaction CONFIGURATIONS long COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/soil/liquefaction.lua -q
           --fps 30 --size 120x42 --out ${CMAKE_CURRENT_BINARY_DIR}/soil-out/liquefaction)
  set_tests_properties(soil_liquefaction PROPERTIES LABELS "soil;long" TIMEOUT 600)
  # Terzaghi with grains: the consolidation scene run whole (four columns, ~80 s); its on_finish
  # asserts the columns' mean degree of consolidation within 10% / 5% / 5% of U(T_v) at T_v = 0.1, 0.2,
  # 0.5 (docs/soil.md §5.2). 120 frames/s: the frames are the scene's samples of settlement.
  add_test(NAME soil_consolidation CONFIGURATIONS long COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/soil/consolidation.lua -q
           --fps 120 --size 100x48 --out ${CMAKE_CURRENT_BINARY_DIR}/soil-out/consolidation)
  set_tests_properties(soil_consolidation PROPERTIES LABELS "soil;long" TIMEOUT 900)
  # The same with one column (default set, ~20 s): the single-column tolerance, 20% (§5.2).
  add_test(NAME soil_consolidation_short COMMAND porelab run ${CMAKE_SOURCE_DIR}/tests/soil/consolidation_short.lua
           --trust -q --fps 120 --size 50x48 --out ${CMAKE_CURRENT_BINARY_DIR}/soil-out/consolidation_short)
  set_tests_properties(soil_consolidation_short PROPERTIES LABELS "soil" TIMEOUT 300)
endif()
# Benchmark (not a test): tests/bench/bench_soil.sh [build/app/porelab] (docs/soil.md §6).
pl_add_c_test(test_servo_drive SOURCES ${PL_TEST_DIR}/soil/test_servo_drive.c LABEL soil TIMEOUT 60)
# Constant-volume simple shear (docs/soil.md §5.4): the undrained pore-pressure rise equals the
# drop of sigma'_v of the dry constant-volume sample. Short (cyclic row, 2 cycles, ~10 s), the
# same with the coupling off (must fail the criterion), and the whole scene (both rows, ~40 s).
if(TARGET porelab)
  add_test(NAME soil_simple_shear COMMAND porelab run ${CMAKE_SOURCE_DIR}/tests/soil/simple_shear_short.lua --trust -q
           --size 160x92 --out ${CMAKE_CURRENT_BINARY_DIR}/soil-out/simple_shear_short)
  set_tests_properties(soil_simple_shear PROPERTIES LABELS "soil" TIMEOUT 120)
  add_test(NAME soil_simple_shear_uncoupled COMMAND porelab run ${CMAKE_SOURCE_DIR}/tests/soil/simple_shear_uncoupled.lua
           --trust -q --size 160x92 --out ${CMAKE_CURRENT_BINARY_DIR}/soil-out/simple_shear_uncoupled)
  set_tests_properties(soil_simple_shear_uncoupled PROPERTIES LABELS "soil" TIMEOUT 120)
  add_test(NAME soil_simple_shear_full CONFIGURATIONS long COMMAND porelab run ${CMAKE_SOURCE_DIR}/tests/soil/simple_shear_check.lua --trust -q
           --size 300x172 --out ${CMAKE_CURRENT_BINARY_DIR}/soil-out/simple_shear_full)
  set_tests_properties(soil_simple_shear_full PROPERTIES LABELS "soil;long" TIMEOUT 300)
endif()
