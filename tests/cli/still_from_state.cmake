# porelab still --at T --from-state DIR starts from the latest restart file at or before T and
# draws the same figure as a still that simulates from t = 0 (byte-identical PNG).
#   cmake -DEXE=porelab -DSCENE=scene.lua -DOUT=dir -DSTEPS=600 -DEVERY=0.03 -DAT=0.1 -P still_from_state.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} run ${SCENE} --steps ${STEPS} --quiet --every 1000000 --save-every ${EVERY}
                        --out ${OUT}/run RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "run failed: ${err}")
endif()
execute_process(COMMAND ${EXE} still ${SCENE} --at ${AT} -o ${OUT}/plain.png --quiet --out ${OUT}/plain
                RESULT_VARIABLE rc1 ERROR_VARIABLE err1)
execute_process(COMMAND ${EXE} still ${SCENE} --at ${AT} -o ${OUT}/resumed.png --out ${OUT}/resumed
                        --from-state ${OUT}/run
                RESULT_VARIABLE rc2 OUTPUT_VARIABLE out2 ERROR_VARIABLE err2)
if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0)
  message(FATAL_ERROR "still failed: ${err1}${err2}")
endif()
if(NOT out2 MATCHES "started from .*state_[0-9.]+\\.plstate")
  message(FATAL_ERROR "the still did not start from a restart file: ${out2}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/plain.png ${OUT}/resumed.png RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "the still from the restart file differs from the one simulated from t = 0")
endif()
message("${out2}")
