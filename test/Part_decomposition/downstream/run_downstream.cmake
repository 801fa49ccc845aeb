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
execute_process(COMMAND ${CMAKE_COMMAND} --build ${PD_WORK_DIR}/build -j2 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "downstream build failed")
endif()
# The same labels from the compiled library and from the headers alone.
foreach(app downstream_app downstream_header_only)
  execute_process(COMMAND ${PD_WORK_DIR}/build/${app} ${PD_MESH} ${PD_WORK_DIR}/${app}.seg
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message(STATUS "${app}: ${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${app} failed")
  endif()
endforeach()
file(READ ${PD_WORK_DIR}/downstream_app.seg compiled)
file(READ ${PD_WORK_DIR}/downstream_header_only.seg header_only)
if(NOT compiled STREQUAL header_only)
  message(FATAL_ERROR "the compiled library and the headers give different labels")
endif()
