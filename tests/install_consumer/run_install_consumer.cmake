# Installs the build tree into a scratch prefix, configures and builds the consumer against it, and
# runs it. Called by CTest with BUILD_DIR, SOURCE_DIR, WORK_DIR, MATERIAL and SCENE defined.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer against the install tree failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/install_consumer ${MATERIAL} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer ran but failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/install_consumer_all ${MATERIAL} ${SCENE}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the find_package(Impact) consumer ran but failed: ${rc}")
endif()
