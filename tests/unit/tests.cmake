# Engine core unit tests.
pl_add_c_test(test_engine_unit SOURCES unit/test_engine_unit.c LABEL unit)
# The core allocator, growable array and PL_ASSERT (engine/src/core).
pl_add_c_test(test_core_alloc SOURCES unit/test_core_alloc.c LABEL unit)
# The include rules of engine/src (tools/check_includes.sh): no module cycle, no Lua/cairo/GL/
# SDL/PLplot header, dem and fluid independent, no fluid model including another.
add_test(NAME engine_include_graph COMMAND sh ${CMAKE_SOURCE_DIR}/tools/check_includes.sh ${CMAKE_SOURCE_DIR}/engine)
# ... and the check itself, on fixture trees: it passes a clean tree and fails each breach.
set(_pl_ig ${CMAKE_CURRENT_SOURCE_DIR}/unit/include_graph)
foreach(_case "clean|0|no cycle" "cycle|1|module cycle dem -> geom -> mesh -> dem"
              "forbidden|1|includes <SDL2/SDL.h>.*includes <lauxlib.h>"
              "dem_fluid|1|dem includes fluid/darcy/darcy.h"
              "cross_model|1|fluid/darcy includes fluid/hydrostatic/hydro.h")
  string(REPLACE "|" ";" _f "${_case}")
  list(GET _f 0 _tree)
  list(GET _f 1 _rc)
  list(GET _f 2 _re)
  add_test(NAME include_graph_fixture_${_tree}
           COMMAND ${CMAKE_COMMAND} -DTOOL=${CMAKE_SOURCE_DIR}/tools/check_includes.sh
                   -DTREE=${_pl_ig}/${_tree} -DRC=${_rc} -DEXPECT=${_re} -P ${_pl_ig}/expect.cmake)
  set_tests_properties(include_graph_fixture_${_tree} PROPERTIES LABELS unit TIMEOUT 30)
endforeach()
set_tests_properties(engine_include_graph PROPERTIES LABELS unit TIMEOUT 30)
# The allocator on whole worlds: no byte left after destroy, no allocation in settled steps.
pl_add_c_test(test_alloc_world SOURCES unit/test_alloc_world.c LABEL unit)
