# Determinism: the same scene run twice gives the same state hash, and the hash does change
# when the state does (one step more), so a constant hash cannot pass.
#   cmake -DEXE=porelab -DSCENE=scene.lua -DOUT=dir -DSTEPS=200 -P determinism.cmake
include(${CMAKE_CURRENT_LIST_DIR}/state_hash.cmake)
function(run_hash steps var)
  pl_state_hash(h --steps ${steps} --every 1000000)
  set(${var} ${h} PARENT_SCOPE)
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
