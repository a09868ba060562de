# cmake --install: the libraries, their headers, the tools and the CMake package (stitchConfig.cmake),
# one export set per component so that a consumer of stitch::core needs no GL.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(STITCH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/stitch)

set(STITCH_COMPONENTS core)
install(TARGETS stitch_core EXPORT stitch-core-targets)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/stitch DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET stitch_render)
  list(APPEND STITCH_COMPONENTS render)
  install(TARGETS stitch_render EXPORT stitch-render-targets)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/render/include/stitch
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
if(TARGET stitch_modeler)
  list(APPEND STITCH_COMPONENTS modeler)
  install(TARGETS stitch_modeler EXPORT stitch-modeler-targets)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/modeler/include/stitch
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
if(TARGET stitch_cad)
  list(APPEND STITCH_COMPONENTS cad)
  install(TARGETS stitch_cad EXPORT stitch-cad-targets)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/cad/include/stitch DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
foreach(component ${STITCH_COMPONENTS})
  install(EXPORT stitch-${component}-targets NAMESPACE stitch:: DESTINATION ${STITCH_CMAKE_DIR})
endforeach()
foreach(tool stitch-cli stitch-modeler)
  if(TARGET ${tool})
    install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/stitchConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/stitchConfig.cmake
                              INSTALL_DESTINATION ${STITCH_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/stitchConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/stitchConfig.cmake ${PROJECT_BINARY_DIR}/stitchConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/StitchOpenSubdiv.cmake
        DESTINATION ${STITCH_CMAKE_DIR})
