# layers/dependency-rules: every `#include "folder/..."` under src/ names a folder of the same or a
# lower layer (docs/design.md, Layout). Run as
#   cmake -DSOURCE_DIR=<repository> -P tests/layers/dependency_rules.cmake
# and fails naming each include that points up.

# The layers, lowest first: the one statement of their order. A folder may include its own files,
# lpe/ (below all of src/), and the folders before it.
set(LAYERS
  math util schema transport sampling geometry accel materials media scene shapes lights film io
  integrators render config bench stress serve cli)

# Known arrows up, each with the work that removes it: none today. An entry reads
# "src/FOLDER/FILE -> FOLDER".
set(ALLOWED "")

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "dependency_rules.cmake: pass -DSOURCE_DIR=<the repository>")
endif()
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/src/*.h ${SOURCE_DIR}/src/*.cpp)
set(violations "")
set(checked 0)
foreach(source IN LISTS sources)
  string(REGEX MATCH "^src/([^/]+)/" _ ${source})
  set(folder ${CMAKE_MATCH_1})
  if(NOT folder)
    continue()  # src/CMakeLists.txt's neighbours, if any
  endif()
  list(FIND LAYERS ${folder} rank)
  if(rank EQUAL -1)
    string(APPEND violations "\n  ${source}: folder ${folder} is in no layer (add it to LAYERS here and to docs/design.md)")
    continue()
  endif()
  file(STRINGS ${SOURCE_DIR}/${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"[^\"]+\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" target "${line}")
    math(EXPR checked "${checked} + 1")
    if(NOT target MATCHES "^([^/]+)/")
      continue()  # a file beside this one
    endif()
    set(to ${CMAKE_MATCH_1})
    if(to STREQUAL "lpe" OR to STREQUAL folder)
      continue()
    endif()
    list(FIND LAYERS ${to} toRank)
    if(toRank EQUAL -1)
      continue()  # not a folder of src/ (a library's own header)
    endif()
    if(toRank GREATER rank)
      list(FIND ALLOWED "${source} -> ${to}" allowed)
      if(allowed EQUAL -1)
        string(APPEND violations "\n  ${source} includes \"${target}\": ${folder} is below ${to}")
      endif()
    endif()
  endforeach()
endforeach()
# Only the command line parses a command line: every other folder is free of CLI11 (the render
# options are plain values, config/render_config.h), so serve and tests configure renders without it.
foreach(source IN LISTS sources)
  if(source MATCHES "^src/cli/")
    continue()
  endif()
  file(STRINGS ${SOURCE_DIR}/${source} parserIncludes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]CLI/")
  if(parserIncludes)
    string(APPEND violations "\n  ${source} includes CLI11: only src/cli/ parses the command line")
  endif()
endforeach()
if(violations)
  string(REPLACE ";" " < " order "${LAYERS}")
  message(FATAL_ERROR "includes that point up the layers (${order}):${violations}")
endif()
message(STATUS "layers: ${checked} includes in src/ follow the layers")
