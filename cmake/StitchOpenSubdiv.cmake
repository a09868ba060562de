# OpenSubdiv's CPU library as the imported target OpenSubdiv::osdCPU. Debian's
# OpenSubdivTargets.cmake names static libraries that libosd-dev does not ship, so
# find_package(OpenSubdiv) fails at configure time: import the shared library directly.
# Used by stitch's own build and by the installed stitchConfig.cmake.
if(NOT TARGET OpenSubdiv::osdCPU)
  find_library(STITCH_OSD_CPU_LIBRARY osdCPU)
  find_path(STITCH_OSD_INCLUDE_DIR opensubdiv/version.h)
  if(NOT STITCH_OSD_CPU_LIBRARY OR NOT STITCH_OSD_INCLUDE_DIR)
    message(FATAL_ERROR "stitch needs OpenSubdiv's osdCPU library and headers (Debian: libosd-dev)")
  endif()
  add_library(OpenSubdiv::osdCPU SHARED IMPORTED)
  set_target_properties(OpenSubdiv::osdCPU PROPERTIES
    IMPORTED_LOCATION ${STITCH_OSD_CPU_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${STITCH_OSD_INCLUDE_DIR})
endif()
