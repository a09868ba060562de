# The folders are the data flow (docs/architecture.md): each stage reads only the stages before it,
# and every include says plainly which stage it reads. Checked on the text of the includes, so a
# new upward include fails here even where the build would still link:
# - `#include "stitch/<stage>/x.hpp"` (public) and `#include "<stage>/x.hpp"` (internal, from
#   src/, the core's private include folder) reach the same stage or an earlier one;
# - no `#include "../x.hpp"`; in the core no bare `#include "x.hpp"` either (always
#   "<stage>/x.hpp"); the libraries over the core (render, cad, output, modeler) keep their
#   private headers beside their sources and include them by their bare name only from there;
# - public headers include public headers only (they are installed without src/);
# - internal helpers shared between files are in stitch::detail, file-private ones in an
#   anonymous namespace: no other private namespace (io_detail, topology_detail, ..._impl).
# Run as cmake -DSTITCH_SOURCE_DIR=<repository> -P layering_test.cmake.
cmake_policy(VERSION 3.20)

# The stages in data-flow order. project/ reads meshes, K-gon controls and the method, and
# nothing below it reads project/, so it sits right after eval/. The core is stitch_core (src/ is
# its private include folder); the rest are libraries over it with include folders of their own.
set(core_stages support mesh topology kgon net eval project tess analysis)
set(library_stages render cad output modeler)
set(stages ${core_stages} ${library_stages})
list(JOIN stages ", " order)
# include/stitch/*.hpp: error.hpp and choices.hpp come before every stage; stitch.hpp is the
# umbrella header for programs that use the library, so nothing inside it includes it.
set(base_headers error.hpp choices.hpp)

set(src ${STITCH_SOURCE_DIR}/src)
set(problems "")
macro(problem text)
  list(APPEND problems "${text}")
endmacro()

# Every folder is a stage in the order, so a new one has to be placed.
file(GLOB folders LIST_DIRECTORIES true RELATIVE ${src} ${src}/*)
file(GLOB public_folders LIST_DIRECTORIES true RELATIVE ${STITCH_SOURCE_DIR}/include/stitch
     ${STITCH_SOURCE_DIR}/include/stitch/*)
foreach(folder ${folders} ${public_folders})
  if(IS_DIRECTORY ${src}/${folder} OR IS_DIRECTORY ${STITCH_SOURCE_DIR}/include/stitch/${folder})
    if(NOT folder IN_LIST stages)
      problem("${folder}/ is not in the stage order of tests/layering_test.cmake")
    endif()
  endif()
endforeach()

function(rank_of stage out)
  list(FIND stages ${stage} r)
  set(${out} ${r} PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE files RELATIVE ${STITCH_SOURCE_DIR} ${src}/*.hpp ${src}/*.cpp
     ${STITCH_SOURCE_DIR}/include/stitch/*.hpp)
set(checked 0)
foreach(file ${files})
  # The including file's stage, and whether it is a public header.
  set(public FALSE)
  if(file MATCHES "^include/stitch/([a-z_]+)/")
    set(stage ${CMAKE_MATCH_1})
    set(public TRUE)
  elseif(file MATCHES "^include/stitch/([a-z_]+\\.hpp)$")
    if(CMAKE_MATCH_1 IN_LIST base_headers)
      set(stage base)
    else()
      set(stage umbrella)
    endif()
    set(public TRUE)
  elseif(file MATCHES "^src/([a-z_]+)/")
    set(stage ${CMAKE_MATCH_1})
    if(file MATCHES "^src/[a-z_]+/include/stitch/")
      set(public TRUE)
    endif()
  else()
    continue()
  endif()
  if(stage STREQUAL "base")
    set(rank -1)
  elseif(stage STREQUAL "umbrella")
    list(FIND stages analysis rank)
  else()
    rank_of(${stage} rank)
  endif()
  get_filename_component(folder ${STITCH_SOURCE_DIR}/${file} DIRECTORY)

  file(STRINGS ${STITCH_SOURCE_DIR}/${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line ${includes})
    math(EXPR checked "${checked} + 1")
    string(REGEX MATCH "\"([^\"]+)\"" _ "${line}")
    set(header ${CMAKE_MATCH_1})
    set(where "${file}: #include \"${header}\"")
    if(header MATCHES "(^|/)\\.\\.?/")
      problem("${where}: a relative path (name the stage instead)")
      continue()
    endif()
    set(target "")
    if(header MATCHES "^stitch/([a-z_]+)\\.hpp$")
      if(CMAKE_MATCH_1 STREQUAL "stitch")
        problem("${where}: the umbrella header is for programs using the library")
      endif()
      continue()  # error.hpp, choices.hpp: before every stage
    elseif(header MATCHES "^stitch/([a-z_]+)/")
      set(target ${CMAKE_MATCH_1})
    elseif(header MATCHES "^([a-z_]+)/")
      set(target ${CMAKE_MATCH_1})
      if(public)
        problem("${where}: a public header includes an internal one")
      elseif(NOT stage IN_LIST core_stages)
        problem("${where}: src/ is the core's private include folder, not ${stage}'s")
      elseif(NOT target IN_LIST core_stages OR NOT EXISTS ${src}/${header})
        problem("${where}: no internal header of the core has this name")
      endif()
    else()
      # A bare name: a private header of a library over the core, beside the file.
      if(public)
        problem("${where}: a public header includes an internal one")
      elseif(stage IN_LIST core_stages)
        problem("${where}: internal headers of the core are included as \"${stage}/${header}\"")
      elseif(NOT EXISTS ${folder}/${header})
        problem("${where}: not beside the file; another stage's header goes by its stage")
      endif()
      continue()
    endif()
    if(NOT target IN_LIST stages)
      if(NOT header MATCHES "^stitch/")  # e.g. <tiny_gltf.h>-style folders of other projects
        problem("${where}: ${target}/ is not a stage")
      endif()
      continue()
    endif()
    rank_of(${target} target_rank)
    if(target_rank GREATER rank)
      problem("${where}: ${stage} comes before ${target} (the order is ${order})")
    endif()
  endforeach()

  # One convention for private namespaces.
  file(STRINGS ${STITCH_SOURCE_DIR}/${file} namespaces
       REGEX "^[ \t]*namespace[ \t]+[A-Za-z_:]*(_detail|_impl|_internal)[ \t]*({|$)")
  foreach(line ${namespaces})
    string(STRIP "${line}" line)
    string(REPLACE ";" "" line "${line}")
    problem("${file}: `${line}`: shared helpers are in stitch::detail, file-private ones in an anonymous namespace")
  endforeach()
endforeach()

list(LENGTH files count)
if(problems)
  list(LENGTH problems n)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "${n} layering problem(s):\n  ${text}")
endif()
message(STATUS "${count} files, ${checked} includes: every one reads its own stage or an earlier one")
