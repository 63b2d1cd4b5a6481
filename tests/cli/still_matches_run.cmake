# `porelab still --at T` must equal the frame `porelab run` draws at T, including what the
# scene's on_frame hooks did before it (the demo opens its gate from a hook at 0.6 s).
# Pixels are compared exactly (imgdiff with zero tolerance): the frame writer and the still
# encode PNG with different compression settings, so the files' bytes differ.
#   cmake -DEXE=porelab -DIMGDIFF=imgdiff -DSCENE=scenes/demo.lua -DOUT=dir -P still_matches_run.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} run ${SCENE} --until 1.0 --size 160x240 --quiet --out ${OUT}/run
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "run failed (${rc}): ${err}")
endif()
execute_process(COMMAND ${EXE} still ${SCENE} --at 1.0 --size 160x240 --quiet
                        --out ${OUT}/still -o ${OUT}/still.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "still failed (${rc}): ${err}")
endif()
execute_process(COMMAND ${EXE} still ${SCENE} --at 0.5 --size 160x240 --quiet
                        --out ${OUT}/still -o ${OUT}/early.png RESULT_VARIABLE rc)
execute_process(COMMAND ${IMGDIFF} ${OUT}/run/frame_000030.png ${OUT}/still.png --channel 0
                        --fraction 0 RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the still at t = 1.0 s differs from the run's frame 30")
endif()
execute_process(COMMAND ${IMGDIFF} ${OUT}/run/frame_000015.png ${OUT}/early.png --channel 0
                        --fraction 0 RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the still at t = 0.5 s differs from the run's frame 15")
endif()
execute_process(COMMAND ${IMGDIFF} ${OUT}/still.png ${OUT}/early.png --channel 0 --fraction 0
                RESULT_VARIABLE same)
if(same EQUAL 0)
  message(FATAL_ERROR "stills at 0.5 s and 1.0 s are identical: nothing moved")
endif()
