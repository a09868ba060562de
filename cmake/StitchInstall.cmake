# cmake --install: the libraries, their headers, the tools and the CMake package (stitchConfig.cmake),
# one export set per component so that a consumer of stitch::core needs no GL.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(STITCH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/stitch)

set(STITCH_COMPONENTS core)
install(TARGETS stitch_core EXPORT stitch-core-targets)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/stitch DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The optional components, each a library with its include root beside its sources.
foreach(component render cad output modeler)
  if(TARGET stitch_${component})
    list(APPEND STITCH_COMPONENTS ${component})
    install(TARGETS stitch_${component} EXPORT stitch-${component}-targets)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/${component}/include/stitch
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()
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
