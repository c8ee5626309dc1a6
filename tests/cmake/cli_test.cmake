# impact_cli_test(<name> PROGRAM <target> CODE <exit code> ARGS <arg>... [EXPECT <regex>...]
#                 [REJECT <regex>...] [LABELS <label>...])
# A CTest test that runs the program (a target name, e.g. mpm) with the arguments and passes only
# if it exits with the code, its stderr matches every EXPECT regular expression and none of the
# REJECT ones (at most 9 each: a false second message is a defect too). Label:
# `integration` unless LABELS says otherwise. Arguments must not contain '|' or ';'.
function(impact_cli_test name)
  cmake_parse_arguments(ARG "" "PROGRAM;CODE" "ARGS;EXPECT;REJECT;LABELS" ${ARGN})
  set(expects)
  set(i 0)
  foreach(pattern IN LISTS ARG_EXPECT)
    math(EXPR i "${i} + 1")
    list(APPEND expects "-DEXPECT_${i}=${pattern}")
  endforeach()
  set(i 0)
  foreach(pattern IN LISTS ARG_REJECT)
    math(EXPR i "${i} + 1")
    list(APPEND expects "-DREJECT_${i}=${pattern}")
  endforeach()
  string(REPLACE ";" "|" args "${ARG_ARGS}")  # ";" would not survive -D
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${ARG_PROGRAM}> "-DARGS=${args}"
                   -DEXIT_CODE=${ARG_CODE} ${expects}
                   -P ${PROJECT_SOURCE_DIR}/tests/cmake/expect_exit.cmake)
  if(NOT ARG_LABELS)
    set(ARG_LABELS integration)
  endif()
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}")
endfunction()
