# Runs one porelab command and checks its exit code and output. Used by tests.cmake:
#   cmake -DEXE=porelab -DARGS="run|scene.lua|--steps|10" -DEXPECT_RC=1
#         [-DMATCH=regex] [-DMATCH2=regex] [-DNOMATCH=regex]
#         [-DEXPECT_FILE=path] [-DFILE_MATCH=regex] [-DNO_FILE=path] -P check.cmake
# EXPECT_RC is an exact code (0 ok, 1 scene or run error, 2 usage error); a crash (signal)
# never matches. MATCH/MATCH2/NOMATCH apply to stdout and stderr together.
string(REPLACE "|" ";" args "${ARGS}")
if(DEFINED EXPECT_FILE)
  file(REMOVE "${EXPECT_FILE}")
endif()
if(DEFINED NO_FILE) # left by an earlier run (or an earlier build): the check must see this one
  file(REMOVE "${NO_FILE}")
endif()
# A fresh output folder each time (a rerun of ctest in the same build must see the same output,
# not "removed N frames of an earlier run"): only folders under the tests' own cli-out.
list(FIND args "--out" _out_at)
if(_out_at GREATER -1)
  math(EXPR _out_at "${_out_at} + 1")
  list(LENGTH args _nargs)
  if(_out_at LESS _nargs)
    list(GET args ${_out_at} _out_dir)
    if(_out_dir MATCHES "/cli-out/" AND NOT DEFINED OUT_DIR) # OUT_DIR: a test that prepares the folder
      file(REMOVE_RECURSE "${_out_dir}")
    endif()
  endif()
endif()
execute_process(COMMAND ${EXE} ${args}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
  WORKING_DIRECTORY "${WORKDIR}")
set(all "${out}${err}")
message("exit code: ${rc}\n--- output ---\n${all}--------------")
if(NOT "${rc}" STREQUAL "${EXPECT_RC}")
  message(FATAL_ERROR "expected exit code ${EXPECT_RC}, got '${rc}'")
endif()
foreach(re MATCH MATCH2)
  if(DEFINED ${re} AND NOT all MATCHES "${${re}}")
    message(FATAL_ERROR "output does not match: ${${re}}")
  endif()
endforeach()
if(DEFINED NOMATCH AND all MATCHES "${NOMATCH}")
  message(FATAL_ERROR "output matches what it must not: ${NOMATCH}")
endif()
if(DEFINED EXPECT_FILE)
  if(NOT EXISTS "${EXPECT_FILE}")
    message(FATAL_ERROR "expected file was not written: ${EXPECT_FILE}")
  endif()
  if(DEFINED FILE_MATCH)
    file(READ "${EXPECT_FILE}" content)
    if(NOT content MATCHES "${FILE_MATCH}")
      message(FATAL_ERROR "${EXPECT_FILE} does not match: ${FILE_MATCH}")
    endif()
  endif()
endif()
if(DEFINED NO_FILE AND EXISTS "${NO_FILE}")
  message(FATAL_ERROR "file must not exist: ${NO_FILE}")
endif()
