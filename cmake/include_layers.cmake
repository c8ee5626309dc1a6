# Layers of folders that include one way only: a folder's files may include its own folder and
# the folders below it, never one above. add_include_layer_check() checks one folder at build
# time (cmake/check_include_layers.cmake, run again when a file of the folder changes) and makes
# `target` wait for the check, so a wrong-way include fails the build before anything compiles.
#
#   add_include_layer_check(<target> PREFIX <dir> FOLDER <folder> LAYERS <bottom> ... <top>
#                           FILES <file> ... [ABOVE <prefix> ...])
# PREFIX is the layered directory as includes name it (pointdriver), FOLDER one of LAYERS, FILES
# the folder's sources and headers (relative to the current source directory, or absolute), ABOVE
# the include prefixes that sit above the whole PREFIX tree (none of its files may include them).
function(add_include_layer_check target)
  cmake_parse_arguments(ARG "" "PREFIX;FOLDER" "LAYERS;FILES;ABOVE" ${ARGN})
  set(relative "")
  foreach(file IN LISTS ARG_FILES)
    cmake_path(ABSOLUTE_PATH file BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} OUTPUT_VARIABLE absolute)
    cmake_path(RELATIVE_PATH absolute BASE_DIRECTORY ${PROJECT_SOURCE_DIR})
    list(APPEND relative ${absolute})
  endforeach()
  list(JOIN relative "|" files)
  list(JOIN ARG_LAYERS "|" layers)
  list(JOIN ARG_ABOVE "|" above)
  string(MAKE_C_IDENTIFIER "${ARG_PREFIX}_${ARG_FOLDER}" name)
  # A folder may list its files in several calls: each call its own check.
  set(base ${name})
  set(n 1)
  while(TARGET ${name}_include_layers)
    math(EXPR n "${n} + 1")
    set(name ${base}_${n})
  endwhile()
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${name}_include_layers.stamp)
  set(script ${PROJECT_SOURCE_DIR}/cmake/check_include_layers.cmake)
  list(TRANSFORM relative PREPEND ${PROJECT_SOURCE_DIR}/ OUTPUT_VARIABLE depends)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR} -DPREFIX=${ARG_PREFIX}
            -DFOLDER=${ARG_FOLDER} -DLAYERS=${layers} -DFILES=${files} -DSTAMP=${stamp}
            -DABOVE=${above}
            -P ${script}
    DEPENDS ${depends} ${script}
    COMMENT "Checking the includes of ${ARG_PREFIX}/${ARG_FOLDER}/"
    VERBATIM)
  add_custom_target(${name}_include_layers DEPENDS ${stamp})
  add_dependencies(${target} ${name}_include_layers)
endfunction()
