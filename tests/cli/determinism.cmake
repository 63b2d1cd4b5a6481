# Determinism: the same scene run twice gives the same state hash, and the hash does change
# when the state does (one step more), so a constant hash cannot pass.
#   cmake -DEXE=porelab -DSCENE=scene.lua -DOUT=dir -DSTEPS=200 -P determinism.cmake
function(run_hash steps var)
  execute_process(COMMAND ${EXE} run ${SCENE} --steps ${steps} --quiet --hash --every 1000000
                          --out ${OUT}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run failed (${rc}): ${out}${err}")
  endif()
  if(NOT out MATCHES "state-hash: ([0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f])\n")
    message(FATAL_ERROR "no 'state-hash: <16 hex digits>' line in: ${out}")
  endif()
  set(${var} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()
run_hash(${STEPS} first)
run_hash(${STEPS} second)
math(EXPR more "${STEPS} + 1")
run_hash(${more} third)
message("hashes: ${first} ${second} (after one more step: ${third})")
if(NOT first STREQUAL second)
  message(FATAL_ERROR "two identical runs gave different state hashes")
endif()
if(first STREQUAL third)
  message(FATAL_ERROR "the state hash did not change after one more step")
endif()
