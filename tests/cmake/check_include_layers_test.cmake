# cmake/check_include_layers.cmake on a small tree (cmake -DWORK_DIR=... -DSCRIPT=... -P this):
# includes that run down pass and write the stamp; one that runs up, or into a folder that is no
# layer, fails the check with a message naming the file, the include and the layers allowed.
file(REMOVE_RECURSE ${WORK_DIR})
file(WRITE ${WORK_DIR}/tree/lib/low/low.hpp "#pragma once\n")
file(WRITE ${WORK_DIR}/tree/lib/mid/mid.cpp
     "#include \"lib/mid/mid.hpp\"\n#include \"lib/low/low.hpp\"\n#include <vector>\n")
file(WRITE ${WORK_DIR}/tree/lib/mid/up.cpp "  #  include \"lib/top/top.hpp\"\n")
file(WRITE ${WORK_DIR}/tree/lib/mid/stray.cpp "#include \"lib/stray/x.hpp\"\n")
file(WRITE ${WORK_DIR}/tree/lib/mid/angle.cpp "#include <lib/top/top.hpp>\n")
file(WRITE ${WORK_DIR}/tree/lib/mid/relative.cpp "#include \"../top/top.hpp\"\n")
file(WRITE ${WORK_DIR}/tree/lib/mid/program.cpp "#include \"app/run.hpp\"\n#include <omp.h>\n")

function(check folder files expected_result expected_output)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK_DIR}/tree -DPREFIX=lib -DFOLDER=${folder}
                          -DLAYERS=low|mid|top -DFILES=${files} -DSTAMP=${WORK_DIR}/${folder}.stamp
                          -DABOVE=app|tools
                          -P ${SCRIPT}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  string(REGEX REPLACE "[ \n]+" " " out "${out}")  # CMake wraps long messages
  if((expected_result EQUAL 0) AND NOT (result EQUAL 0))
    message(FATAL_ERROR "${folder} (${files}): expected to pass, got: ${out}")
  endif()
  if(NOT (expected_result EQUAL 0) AND (result EQUAL 0))
    message(FATAL_ERROR "${folder} (${files}): expected to fail, passed")
  endif()
  string(FIND "${out}" "${expected_output}" at)
  if(at LESS 0)
    message(FATAL_ERROR "${folder} (${files}): expected '${expected_output}' in: ${out}")
  endif()
endfunction()

check(mid lib/mid/mid.cpp 0 "")
if(NOT EXISTS ${WORK_DIR}/mid.stamp)
  message(FATAL_ERROR "a passing check writes its stamp")
endif()
check(low lib/low/low.hpp 0 "")
check(mid lib/mid/mid.cpp|lib/mid/up.cpp 1
      "lib/mid/up.cpp includes lib/top/top.hpp: mid/ may include only low/ (and its own files)")
check(mid lib/mid/stray.cpp 1
      "lib/mid/stray.cpp includes lib/stray/x.hpp: stray/ is not one of the layers of lib/ (low, mid, top)")
check(mid lib/mid/angle.cpp 1
      "lib/mid/angle.cpp includes lib/top/top.hpp: mid/ may include only low/ (and its own files)")
check(mid lib/mid/relative.cpp 1 "lib/mid/relative.cpp includes ../top/top.hpp: a relative path")
check(mid lib/mid/program.cpp 1 "lib/mid/program.cpp includes app/run.hpp: app/ is above lib/")
