# `porelab run scene --out ""` must be refused (it reported "frames in /"). A CMake list
# cannot carry an empty argument, so this runs the command itself.
execute_process(COMMAND ${EXE} run scenes/five_discs.lua --steps 1 --quiet --out ""
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY "${WORKDIR}")
message("exit code: ${rc}\n--- output ---\n${out}${err}--------------")
if(NOT "${rc}" STREQUAL "2")
  message(FATAL_ERROR "expected exit code 2, got '${rc}'")
endif()
if(NOT "${out}${err}" MATCHES "porelab run: --out must name a folder \\(got ''")
  message(FATAL_ERROR "the message does not say that --out is empty")
endif()
