# Runs PROGRAM with the arguments ARGS ('|'-separated, so that JSON patches keep their commas and
# semicolons are never involved) and passes only if it exits with EXIT_CODE and its stderr matches
# every regular expression EXPECT_1, EXPECT_2, ... Used for the bad-input tests of `pointdriver run`
# (tests/models/material/expect_input_error.cmake takes one input and no sub-command).
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${PROGRAM} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc STREQUAL EXIT_CODE)
  message(FATAL_ERROR "expected exit code ${EXIT_CODE}, got ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
foreach(i RANGE 1 9)
  if(DEFINED EXPECT_${i} AND NOT err MATCHES "${EXPECT_${i}}")
    message(FATAL_ERROR "stderr does not match '${EXPECT_${i}}':\n${err}")
  endif()
endforeach()
message(STATUS "exit ${rc} with the expected message:\n${err}")
