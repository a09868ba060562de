# The core library alone: configured with every optional part off, it must neither look for nor
# link anything of GL, EGL, GLFW, ImGui or stb, and must build.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${STITCH_SOURCE_DIR} -B ${WORK_DIR} -DCMAKE_BUILD_TYPE=Release
          -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DSTITCH_BUILD_RENDER=OFF -DSTITCH_BUILD_APPS=OFF
          -DSTITCH_BUILD_MODELER=OFF -DSTITCH_BUILD_TESTS=OFF -DSTITCH_BUILD_BENCH=OFF
          -DSTITCH_BUILD_PYTHON=OFF
  OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
file(STRINGS ${WORK_DIR}/CMakeCache.txt gl_entries REGEX "^(EPOXY|EGL|GLFW|IMGUI|STB|OpenGL)_")
if(gl_entries)
  message(FATAL_ERROR "the core-only configuration looked for GUI/GL packages: ${gl_entries}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR} --target stitch_core -j 2
                OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
file(GLOB_RECURSE link_files ${WORK_DIR}/*.make ${WORK_DIR}/*link.txt)
foreach(file ${link_files})
  file(STRINGS ${file} hits REGEX "epoxy|EGL|glfw|imgui|libGL")
  if(hits)
    message(FATAL_ERROR "${file} names a GL library: ${hits}")
  endif()
endforeach()
