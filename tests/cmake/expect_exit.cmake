# Runs PROGRAM with the arguments ARGS ('|'-separated, so that JSON patches keep their commas and
# semicolons are never involved) and passes only if it exits with EXIT_CODE and its stderr matches
# every regular expression EXPECT_1, EXPECT_2, ... (up to EXPECT_9) and none of REJECT_1, ...
# (up to REJECT_9). The one script behind every
# command-line test (impact_cli_test in cli_test.cmake): mpm, pointdriver and material_check.
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${PROGRAM} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc STREQUAL EXIT_CODE)
  message(FATAL_ERROR "expected exit code ${EXIT_CODE}, got ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
foreach(i RANGE 1 9)
  if(DEFINED EXPECT_${i} AND NOT err MATCHES "${EXPECT_${i}}")
    message(FATAL_ERROR "stderr does not match '${EXPECT_${i}}':\n${err}")
  endif()
  if(DEFINED REJECT_${i} AND err MATCHES "${REJECT_${i}}")
    message(FATAL_ERROR "stderr matches '${REJECT_${i}}', which it must not:\n${err}")
  endif()
endforeach()
message(STATUS "exit ${rc} as expected:\n${err}")
