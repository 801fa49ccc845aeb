# Installs the package into a staging prefix, then configures, builds and runs a downstream project
# that only knows find_package(Part_decomposition).
file(REMOVE_RECURSE ${PD_WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${PD_BINARY_DIR} --prefix ${PD_WORK_DIR}/prefix
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${PD_DOWNSTREAM_SOURCE} -B ${PD_WORK_DIR}/build
                        -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${PD_WORK_DIR}/prefix
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "downstream configure failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${PD_WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "downstream build failed")
endif()
execute_process(COMMAND ${PD_WORK_DIR}/build/downstream_app RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "downstream program failed")
endif()
