# Runs PROGRAM with ARGS (a ;-list) and passes only if it exits with EXIT_CODE and its stderr
# matches every regular expression EXPECT_1, EXPECT_2, ... (the mpm command-line tests).
string(REPLACE "|" ";" ARGS "${ARGS}")  # the caller joins arguments with |
execute_process(COMMAND ${PROGRAM} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc STREQUAL EXIT_CODE)
  message(FATAL_ERROR "expected exit code ${EXIT_CODE}, got ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
foreach(i RANGE 1 9)
  if(DEFINED EXPECT_${i} AND NOT err MATCHES "${EXPECT_${i}}")
    message(FATAL_ERROR "stderr does not match '${EXPECT_${i}}':\n${err}")
  endif()
endforeach()
message(STATUS "exit ${rc} as expected:\n${err}")
