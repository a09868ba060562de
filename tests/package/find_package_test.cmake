# cmake --install of a finished build into WORK_DIR/prefix, then the tutorial of docs/library.md as
# its own project against that prefix, built and run. Fails on the first step that fails.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${STITCH_BUILD_DIR} --prefix ${prefix}
                OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
foreach(file include/stitch/stitch.hpp lib/cmake/stitch/stitchConfig.cmake
             lib/cmake/stitch/stitchConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "cmake --install did not install ${file}")
  endif()
endforeach()
# Internal headers stay internal.
file(GLOB_RECURSE internal ${prefix}/include/*split_net.hpp ${prefix}/include/*opensubdiv_topology.hpp)
if(internal)
  message(FATAL_ERROR "internal headers were installed: ${internal}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
                        -DTUTORIAL_SOURCE=${TUTORIAL_SOURCE} -DWITH_MODELER=${WITH_MODELER}
                COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${WORK_DIR}/build/consumer ${TUTORIAL_MESH} ${WORK_DIR}/out
                COMMAND_ERROR_IS_FATAL ANY)
if(WITH_MODELER)
  execute_process(COMMAND ${WORK_DIR}/build/modeler_consumer COMMAND_ERROR_IS_FATAL ANY)
endif()
