# Finite-element solid tests (label "solids"; docs/solids.md). Each test prints its measured
# numbers and the closed form or published value beside it. They mesh with gmsh, so they are
# built only when the engine has it (PL_HAVE_GMSH=1 on porelab_engine).
get_target_property(_pl_engine_defs porelab_engine INTERFACE_COMPILE_DEFINITIONS)
if("${_pl_engine_defs}" MATCHES "PL_HAVE_GMSH=1")
  pl_add_c_test(test_solid_elastic SOURCES ${PL_TEST_DIR}/solids/test_solid_elastic.c LABEL solids TIMEOUT 120)
  set_tests_properties(test_solid_elastic PROPERTIES ENVIRONMENT "PL_TEST_ONLY=wave,crit,cant")
  add_test(NAME test_solid_lame COMMAND test_solid_elastic)
  set_tests_properties(test_solid_lame PROPERTIES ENVIRONMENT "PL_TEST_ONLY=lame" LABELS solids TIMEOUT 120)
endif()
if("${_pl_engine_defs}" MATCHES "PL_HAVE_GMSH=1")
  pl_add_c_test(test_solid_world SOURCES ${PL_TEST_DIR}/solids/test_solid_world.c LABEL solids TIMEOUT 120)
  pl_add_c_test(test_solid_load_work SOURCES ${PL_TEST_DIR}/solids/test_solid_load_work.c LABEL solids TIMEOUT 60)
endif()
if("${_pl_engine_defs}" MATCHES "PL_HAVE_GMSH=1")
  pl_add_c_test(test_solid_plastic SOURCES ${PL_TEST_DIR}/solids/test_solid_plastic.c LABEL solids TIMEOUT 60)
  add_test(NAME test_solid_punch CONFIGURATIONS long COMMAND test_solid_plastic punch)
  set_tests_properties(test_solid_punch PROPERTIES LABELS "solids;long" TIMEOUT 900)
endif()
# Scenes of scenes/solids/ run to their end (imperative scripts with their own asserts).
if("${_pl_engine_defs}" MATCHES "PL_HAVE_GMSH=1" AND TARGET porelab)
  foreach(scene cutting cutting_frames projectile buried_pipe mesh_file glued_layer)
    add_test(NAME solid_scene_${scene} COMMAND porelab run ${CMAKE_SOURCE_DIR}/scenes/solids/${scene}.lua -q
             --out ${CMAKE_CURRENT_BINARY_DIR}/solids-out/${scene})
    set_tests_properties(solid_scene_${scene} PROPERTIES LABELS solids TIMEOUT 120)
  endforeach()
endif()
# Cook's membrane (nearly incompressible): 2..16 here; "long" adds 32x32 and, with a folder,
# writes the convergence chart:  build/tests/test_solid_cook long docs/figures
if("${_pl_engine_defs}" MATCHES "PL_HAVE_GMSH=1")
  pl_add_c_test(test_solid_cook SOURCES ${PL_TEST_DIR}/solids/test_solid_cook.c LABEL solids TIMEOUT 120)
  add_test(NAME test_solid_cook_long CONFIGURATIONS long COMMAND test_solid_cook long)
  set_tests_properties(test_solid_cook_long PROPERTIES LABELS "solids;long" TIMEOUT 600)
  if(TARGET porelab_render)
    target_link_libraries(test_solid_cook PRIVATE porelab_render)
    target_include_directories(test_solid_cook PRIVATE ${CMAKE_SOURCE_DIR}/app/render)
    target_compile_definitions(test_solid_cook PRIVATE PL_SOLID_CHART=1)
  endif()
endif()
# Reading a part from a gmsh .msh file (writes its files into the build folder).
if("${_pl_engine_defs}" MATCHES "PL_HAVE_GMSH=1")
  pl_add_c_test(test_solid_mesh_file SOURCES ${PL_TEST_DIR}/solids/test_solid_mesh_file.c LABEL solids TIMEOUT 60)
  set_tests_properties(test_solid_mesh_file PROPERTIES WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endif()
if("${_pl_engine_defs}" MATCHES "PL_HAVE_GMSH=1" AND TARGET porelab)
  add_test(NAME solid_mesh_outside_folder COMMAND porelab run ${PL_TEST_DIR}/solids/bad_mesh_path.lua -q
           --out ${CMAKE_CURRENT_BINARY_DIR}/solids-out/bad_mesh_path)
  set_tests_properties(solid_mesh_outside_folder PROPERTIES LABELS solids TIMEOUT 30
                       PASS_REGULAR_EXPRESSION "solid_mesh: reading '../../scenes/solids/plate_hole.msh' is not allowed in a sandboxed scene")
endif()
