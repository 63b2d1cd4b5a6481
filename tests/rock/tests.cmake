# Bonded rock, heat and wear (porelab/bonds.h, docs/rock.md): closed-form checks.
pl_add_c_test(test_bond_laws SOURCES rock/test_bond_laws.c LABEL physics)
pl_add_c_test(test_lattice SOURCES rock/test_lattice.c LABEL physics)
pl_add_c_test(test_rock_state SOURCES rock/test_rock_state.c LABEL physics)
pl_add_c_test(test_heat_wear SOURCES rock/test_heat_wear.c LABEL physics)
pl_add_c_test(test_heat_wear_polygon SOURCES rock/test_heat_wear_polygon.c LABEL physics)
pl_add_c_test(test_bond_beam SOURCES rock/test_bond_beam.c LABEL physics)

# Short versions of the laboratory scenes (scenes/rock): a small specimen must be bonded at
# rest (no bond broken before loading) and give a peak strength and moduli.
function(pl_rock_cli name)
  cmake_parse_arguments(T "" "MATCH;MATCH2" "ARGS" ${ARGN})
  string(REPLACE ";" "|" args "${T_ARGS}")
  add_test(NAME cli_rock_${name} COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:porelab> "-DARGS=${args}"
           -DEXPECT_RC=0 -DWORKDIR=${CMAKE_SOURCE_DIR} "-DMATCH=${T_MATCH}" "-DMATCH2=${T_MATCH2}"
           -P ${CMAKE_CURRENT_LIST_DIR}/../cli/check.cmake)
  set_tests_properties(cli_rock_${name} PROPERTIES LABELS cli TIMEOUT 120)
endfunction()
set(pl_rock_out ${CMAKE_CURRENT_BINARY_DIR}/cli-out/rock)
pl_rock_cli(ucs_short ARGS run scenes/rock/ucs.lua --param width=25 --param strain_max=0.2 --no-frames
                           --out ${pl_rock_out}/ucs
  MATCH "bonds intact after the side walls went \\(0 broke\\)"
  MATCH2 "ucs: E = [1-9][0-9.]* GPa, nu = 0\\.[0-9]+, UCS = [1-9][0-9.]* MPa")
pl_rock_cli(brazilian_short ARGS run scenes/rock/brazilian.lua --param size=30 --no-frames
                                 --out ${pl_rock_out}/brazilian
  MATCH "bonds intact at rest \\(0 broke\\)"
  MATCH2 "sigma_t = 2P/\\(pi D\\) = [1-9][0-9.]* MPa")
pl_rock_cli(punch_short ARGS run scenes/rock/punch.lua --param size=30 --param depth=0.1 --no-frames
                             --out ${pl_rock_out}/punch
  MATCH "bonds intact \\(0 broke at rest\\)"
  MATCH2 "punch: peak force [1-9][0-9.e+]* N/m")
pl_rock_cli(cutting_short ARGS run scenes/rock/cutting.lua --param length=40 --param passes=2 --no-frames
                               --out ${pl_rock_out}/cutting
  MATCH "cutting: 2 passes, [0-9.]+ ms of cutting; mean cutting force [1-9]"
  MATCH2 "tool mass loss [0-9.]*[1-9][0-9.]* g/m")
