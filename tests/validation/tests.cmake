# docs/validation.md generated from the tests' own output (issue 13 item 10).
# PL_VALIDATION_TESTS: the tests behind the validation tables, in the tables' order; each
# prints its rows with pl_validation (tests/harness.h) or, for a Lua scene, print("VALIDATION|...").
#   validation_doc      (label validation-doc, configuration validation-doc: not in the plain run)
#                       runs them all (~5 min on 2 cores, the long ones included) and rewrites
#                       the tables of docs/validation.md between the "generated" markers:
#                       ctest --test-dir build -C validation-doc -L validation-doc
#   validation_doc_ids  (default set, label validation) every row of the document is printed by a
#                       test and every row a C test prints is in the document, without running them.
# To check the numbers without writing: cmake -DMODE=check ... -P tests/validation/validation_doc.cmake
# (same arguments as the validation_doc test; ctest -C validation-doc -L validation-doc -V shows them).
set(PL_VALIDATION_TESTS
  test_seed003_validation test_contact_laws test_engine_unit test_boundary_motion
  test_polygon_geometry test_polygon_contact test_polygon_incline test_polygon_determinism test_polygon_heap
  test_fluid_static test_fluid_mesh test_fluid_buoyancy test_fluid_edge test_fluid_wave test_fluid_bed test_fluid_porosity
  test_fluid_frame test_fluid_snapshot test_ns_flow test_ns_validation test_ns_validation_dfg
  test_ns_validation_plates test_ns_world_long
  test_soil_terzaghi test_soil_undrained test_soil_overburden test_soil_quicksand soil_consolidation_short
  soil_consolidation soil_liquefaction soil_simple_shear soil_simple_shear_uncoupled soil_simple_shear_full
  test_solid_elastic test_solid_lame test_solid_plastic test_solid_world test_solid_load_work test_solid_cook test_solid_punch)
set(PL_VALIDATION_LONG soil_consolidation soil_liquefaction soil_simple_shear_full test_ns_world_long test_solid_punch)
set(_pl_vt "")
foreach(t IN LISTS PL_VALIDATION_TESTS)
  if(TEST ${t})
    list(APPEND _pl_vt ${t})
  endif()
endforeach()
list(JOIN _pl_vt "|" _pl_vt)
list(JOIN PL_VALIDATION_LONG "|" _pl_vl)
add_test(NAME validation_doc CONFIGURATIONS validation-doc
  COMMAND ${CMAKE_COMMAND} -DCTEST=${CMAKE_CTEST_COMMAND} -DBUILD=${CMAKE_BINARY_DIR}
          -DDOC=${CMAKE_SOURCE_DIR}/docs/validation.md "-DTESTS=${_pl_vt}" "-DLONG=${_pl_vl}"
          -P ${CMAKE_CURRENT_LIST_DIR}/validation_doc.cmake)
set_tests_properties(validation_doc PROPERTIES LABELS validation-doc TIMEOUT 1800 RUN_SERIAL TRUE)
add_test(NAME validation_doc_ids
  COMMAND ${CMAKE_COMMAND} -DDOC=${CMAKE_SOURCE_DIR}/docs/validation.md -DSRC=${CMAKE_SOURCE_DIR}
          "-DTESTS=${_pl_vt}" -P ${CMAKE_CURRENT_LIST_DIR}/validation_ids.cmake)
set_tests_properties(validation_doc_ids PROPERTIES LABELS validation TIMEOUT 60)
