# Runs tools/check_includes.sh on a fixture tree and checks its verdict, so the include check
# is shown to fail on a tree that breaks a rule (and to pass on a clean one).
#   cmake -DTOOL=check_includes.sh -DTREE=dir -DRC=0|1 [-DEXPECT=regex] -P expect.cmake
execute_process(COMMAND sh ${TOOL} ${TREE} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL RC)
  message(FATAL_ERROR "check_includes.sh on ${TREE} exited ${rc}, expected ${RC}")
endif()
if(DEFINED EXPECT AND NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "check_includes.sh on ${TREE}: output does not match '${EXPECT}'")
endif()
