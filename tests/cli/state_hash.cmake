# pl_state_hash(VAR ARGS...): runs `${EXE} run ${SCENE} ARGS... --quiet --hash --out ${OUT}` and
# sets VAR to the state hash it prints; a failed run or a missing hash line stops the test.
# Shared by determinism.cmake, threads.cmake and frames_neutral.cmake.
function(pl_state_hash var)
  execute_process(COMMAND ${EXE} run ${SCENE} ${ARGN} --quiet --hash --out ${OUT}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run with '${ARGN}' failed (${rc}): ${out}${err}")
  endif()
  if(NOT out MATCHES "state-hash: ([0-9a-f]+)\n")
    message(FATAL_ERROR "no 'state-hash:' line in: ${out}")
  endif()
  set(${var} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()
