# Drawing is read-only: a run that draws the fluid in its frames ends in the same state as the
# same run without frames (a model's preparation for the first picture must not change what the
# steps do), and the hash does change with one step more, so a constant hash cannot pass.
#   cmake -DEXE=porelab -DSCENE=scene.lua -DOUT=dir -DSTEPS=40 -DEVERY=20 -P frames_neutral.cmake
include(${CMAKE_CURRENT_LIST_DIR}/state_hash.cmake)
function(run_hash steps var)
  pl_state_hash(h --steps ${steps} ${ARGN})
  set(${var} ${h} PARENT_SCOPE)
endfunction()
run_hash(${STEPS} drawn --every ${EVERY} --size 160x90 --layers bodies,pressure,velocity,mesh)
run_hash(${STEPS} plain --no-frames)
math(EXPR more "${STEPS} + 1")
run_hash(${more} third --no-frames)
message("hashes: with frames of the fluid ${drawn}, without frames ${plain} (one step more: ${third})")
if(NOT drawn STREQUAL plain)
  message(FATAL_ERROR "drawing the fluid changed the state")
endif()
if(plain STREQUAL third)
  message(FATAL_ERROR "the state hash did not change after one more step")
endif()
