# The repository stands alone: no tracked file refers to a folder beside it. A user's clone has
# nothing beside it, so a path into the folder that CI has beside it (shared/) would fail there,
# and only a search of the tree can tell.
cmake_policy(VERSION 3.20)
find_package(Git REQUIRED)
execute_process(COMMAND ${GIT_EXECUTABLE} -C ${STITCH_SOURCE_DIR} ls-files -co --exclude-standard
                OUTPUT_VARIABLE files COMMAND_ERROR_IS_FATAL ANY)
string(REPLACE "\n" ";" files "${files}")
set(needle "..")
string(APPEND needle "/shared")  # spelled in two parts so that this file does not match itself
set(offenders "")
foreach(file ${files})
  if(file MATCHES "\\.(png|jpg|ply|glb)$" OR NOT EXISTS ${STITCH_SOURCE_DIR}/${file})
    continue()
  endif()
  file(READ ${STITCH_SOURCE_DIR}/${file} text)
  string(FIND "${text}" "${needle}" at)
  if(NOT at EQUAL -1)
    list(APPEND offenders ${file})
  endif()
endforeach()
list(LENGTH files count)
if(offenders)
  message(FATAL_ERROR "these files refer to ${needle}, outside the repository: ${offenders}")
endif()
message(STATUS "${count} files, none refers to a folder outside the repository")
