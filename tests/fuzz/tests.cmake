# Fuzzing porelab run (issue 13, "Fuzzing in CI"; tests/fuzz/fuzz.sh says what is checked).
#   fuzz       (default set, label fuzz) the hand-written cases of the default set and 250
#              mutations of scenes/**, seed 13, 2 at a time: about 40 s on 2 cores
#   fuzz_long  (label fuzz-long, configuration fuzz-long: not in the plain run) every hand-written
#              case (endless loops, memory bombs: each costs its budget) and 3000 mutations:
#              ctest --test-dir build -C fuzz-long -L fuzz-long
# The cases, their output and the failures stay in <build>/tests/fuzz-out/<test>/.
set(PL_FUZZ ${CMAKE_CURRENT_LIST_DIR}/fuzz.sh)
add_test(NAME fuzz COMMAND sh ${PL_FUZZ} $<TARGET_FILE:porelab> ${CMAKE_SOURCE_DIR}
         ${CMAKE_CURRENT_BINARY_DIR}/fuzz-out/fuzz --seed 13 --mutations 250 --jobs 2
         --budget 40 --cpu 10 --deadline 100)
set_tests_properties(fuzz PROPERTIES LABELS fuzz TIMEOUT 180)
add_test(NAME fuzz_long CONFIGURATIONS fuzz-long COMMAND sh ${PL_FUZZ} $<TARGET_FILE:porelab> ${CMAKE_SOURCE_DIR}
         ${CMAKE_CURRENT_BINARY_DIR}/fuzz-out/fuzz_long --seed 13 --mutations 3000 --set long --jobs 2
         --budget 20 --cpu 20 --deadline 3000)
set_tests_properties(fuzz_long PROPERTIES LABELS fuzz-long TIMEOUT 3600)
