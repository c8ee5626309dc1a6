# Fails when a file of one folder includes a folder above it (cmake -P; added by
# include_layers.cmake, which passes):
#   ROOT    the source directory the include paths start from
#   PREFIX  the layered directory below ROOT, e.g. pointdriver (includes read "PREFIX/<folder>/...")
#   FOLDER  the folder checked, e.g. fit
#   LAYERS  the folders bottom up, '|'-separated (a ';' list cannot pass the command line whole)
#   FILES   the folder's files, '|'-separated, relative to ROOT
#   STAMP   written when every include runs down (or stays in FOLDER)
#   ABOVE   optional: include prefixes above the whole PREFIX tree, '|'-separated (e.g. campaigns
#           for mpm: no file of mpm/ may include "campaigns/...")
# Quoted and angle-bracket includes are both read; a relative include ("../x.hpp") is refused,
# since it would step around the check.
# One message per wrong include, all of them at once:
#   "pointdriver/fit/fit_report.cpp includes pointdriver/commands/options.hpp: fit/ may include
#   only path/, driver/, ... (and its own files)"
cmake_minimum_required(VERSION 3.25)  # script mode: IN_LIST, SUBLIST and the policies of the project
string(REPLACE "|" ";" layers "${LAYERS}")
string(REPLACE "|" ";" files "${FILES}")
string(REPLACE "|" ", " layer_list "${LAYERS}")
list(FIND layers "${FOLDER}" level)
if(level LESS 0)
  message(FATAL_ERROR "${PREFIX}/${FOLDER}/ is not one of the layers (${layer_list})")
endif()
list(SUBLIST layers 0 ${level} below)
set(allowed "")
foreach(layer IN LISTS below)
  string(APPEND allowed "${layer}/, ")
endforeach()
if(allowed STREQUAL "")
  set(allowed "its own files (it is the lowest layer)")
else()
  string(REGEX REPLACE ", $" " (and its own files)" allowed "${allowed}")
endif()

set(problems "")
string(REPLACE "|" ";" above "${ABOVE}")
foreach(file IN LISTS files)
  file(STRINGS "${ROOT}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"<]*[\"<]([^\">]+)[\">].*$" "\\1" header "${line}")
    if(header MATCHES "^\\.\\./|/\\.\\./")
      string(APPEND problems "\n  ${file} includes ${header}: a relative path; include it as "
                             "\"${PREFIX}/<folder>/<name>\"")
      continue()
    endif()
    string(REGEX REPLACE "/.*$" "" top "${header}")
    if(top IN_LIST above)
      string(APPEND problems "\n  ${file} includes ${header}: ${top}/ is above ${PREFIX}/")
      continue()
    endif()
    if(NOT header MATCHES "^${PREFIX}/[^/]+/")
      continue()
    endif()
    string(REGEX REPLACE "^${PREFIX}/([^/]+)/.*$" "\\1" included "${header}")
    if(included STREQUAL FOLDER OR included IN_LIST below)
      continue()
    endif()
    if(included IN_LIST layers)
      string(APPEND problems "\n  ${file} includes ${header}: ${FOLDER}/ may include only ${allowed}")
    else()
      string(APPEND problems "\n  ${file} includes ${header}: ${included}/ is not one of the layers "
                             "of ${PREFIX}/ (${layer_list})")
    endif()
  endforeach()
endforeach()
if(NOT problems STREQUAL "")
  message(FATAL_ERROR "wrong-way include (a layer may include only the layers below it):${problems}")
endif()
file(TOUCH "${STAMP}")
