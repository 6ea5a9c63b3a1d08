# The library graph (docs/design.md section 4), one-way:
#   core <- law <- result <- analysis ; core <- specimen <- analysis ;
#   law + specimen + result <- beam, mpm, fem (each on its own) ;
#   core <- dic (DIC frames) <- result (the virtual DIC test writes frames in dic's layouts) ; analysis + beam <- identify ; everything <- app <- python.
# FIBERBRIDGE_LAYER_<lib> lists the libraries whose headers the sources of <lib> may include
# (besides its own). fiberbridge_check_layer(<lib>) enforces it at configure time: every
# `#include "fiberbridge/<dir>/..."` in source/<lib>/ and include/fiberbridge/<lib>/ must name
# <lib> or one of those; another one stops the configure with the file, line and the rule.
set(FIBERBRIDGE_LAYER_core "")
set(FIBERBRIDGE_LAYER_law core)
set(FIBERBRIDGE_LAYER_specimen core)
set(FIBERBRIDGE_LAYER_result dic law core)
set(FIBERBRIDGE_LAYER_analysis result specimen law core)
set(FIBERBRIDGE_LAYER_dic core)
# Every simulation model (FIBERBRIDGE_ALL_MODELS, the top CMakeLists.txt) speaks law, specimen and
# result, and never sees another model: a new model needs no line here.
foreach(model ${FIBERBRIDGE_ALL_MODELS})
  set(FIBERBRIDGE_LAYER_${model} result specimen law core)
endforeach()
set(FIBERBRIDGE_LAYER_identify beam analysis result specimen law core)
set(FIBERBRIDGE_LAYER_app identify ${FIBERBRIDGE_ALL_MODELS} dic analysis result specimen law core)
# The Python module binds the app's typed API (and what its outcomes hold) for Python scripts.
set(FIBERBRIDGE_LAYER_python app identify ${FIBERBRIDGE_ALL_MODELS} dic analysis result specimen law
                             core)

# The app's rooms (docs/design.md section 4, "The app's rooms"), one-way like the libraries:
#   scene <- outputs <- run <- items <- cli.
# scene: the reader, SceneParameters, the context, the sections, the registries' interfaces and
# the step outcomes; outputs: every writer, the report and the run directory; run: resume, the
# task hand-out, the scene runner; items: one file per item, the steps they share, the registries'
# entries; cli: main and the commands. FIBERBRIDGE_ROOM_<room> lists the rooms <room> may include
# besides its own: outputs and run never include items. A room's files are
# source/app/<room>/ and include/fiberbridge/app/<room>/; they name another room's headers as
# "fiberbridge/app/<room>/x.h" (public) or "<room>/x.h" (private, under source/app).
set(FIBERBRIDGE_APP_ROOMS scene outputs run items cli)
set(FIBERBRIDGE_ROOM_scene "")
set(FIBERBRIDGE_ROOM_outputs scene)
set(FIBERBRIDGE_ROOM_run outputs scene)
set(FIBERBRIDGE_ROOM_items run outputs scene)
set(FIBERBRIDGE_ROOM_cli items run outputs scene)

# Appends to `out_var` one line per include in the sources and headers of `dirs` (relative to the
# project) that `include_regex` matches and whose dependency (group `dep_group` of `dep_regex`) is
# not in `allowed`; `why` ends each line.
function(fiberbridge_include_violations out_var dirs include_regex dep_regex dep_group allowed why)
  set(violations "${${out_var}}")
  set(globs "")
  foreach(d ${dirs})
    list(APPEND globs ${PROJECT_SOURCE_DIR}/${d}/*.cc ${PROJECT_SOURCE_DIR}/${d}/*.h)
  endforeach()
  file(GLOB_RECURSE files ${globs})
  foreach(f ${files})
    file(STRINGS ${f} lines REGEX "${include_regex}")
    foreach(line ${lines})
      string(REGEX REPLACE "${dep_regex}" "\\${dep_group}" dep "${line}")
      if(NOT dep IN_LIST allowed)
        file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${f})
        string(APPEND violations "\n  ${rel}: ${line}${why}")
      endif()
    endforeach()
  endforeach()
  set(${out_var} "${violations}" PARENT_SCOPE)
endfunction()

function(fiberbridge_check_layer lib)
  if(NOT DEFINED FIBERBRIDGE_LAYER_${lib})
    message(FATAL_ERROR "cmake/fiberbridge_layers.cmake: library '${lib}' has no layer rule; add "
                        "FIBERBRIDGE_LAYER_${lib} (docs/design.md section 4)")
  endif()
  set(allowed ${lib} ${FIBERBRIDGE_LAYER_${lib}})
  set(violations "")
  fiberbridge_include_violations(violations "source/${lib};include/fiberbridge/${lib}"
                                 "^[ \t]*#[ \t]*include[ \t]*[\"<]fiberbridge/"
                                 "^[^\"<]*[\"<]fiberbridge/([^/\">]+)/.*$" 1 "${allowed}" "")
  if(violations)
    string(REPLACE ";" " " allowed_text "${allowed}")
    message(FATAL_ERROR "Library '${lib}' may include headers of ${allowed_text} only "
                        "(cmake/fiberbridge_layers.cmake, docs/design.md section 4):${violations}")
  endif()
endfunction()

# The app's rooms (FIBERBRIDGE_ROOM_<room> above): every app include of another room must be one
# the rule allows, and every app source must sit in a room (no file flat in source/app).
function(fiberbridge_check_app_rooms)
  set(violations "")
  file(GLOB stray ${PROJECT_SOURCE_DIR}/source/app/*.cc ${PROJECT_SOURCE_DIR}/source/app/*.h
                  ${PROJECT_SOURCE_DIR}/include/fiberbridge/app/*.h)
  string(REPLACE ";" ", " rooms_text "${FIBERBRIDGE_APP_ROOMS}")
  foreach(f ${stray})
    file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${f})
    string(APPEND violations "\n  ${rel}: in no room (move it to one of ${rooms_text})")
  endforeach()
  string(REPLACE ";" "|" rooms_re "${FIBERBRIDGE_APP_ROOMS}")
  foreach(room ${FIBERBRIDGE_APP_ROOMS})
    set(allowed ${room} ${FIBERBRIDGE_ROOM_${room}})
    string(REPLACE ";" " " allowed_text "${allowed}")
    fiberbridge_include_violations(violations "source/app/${room};include/fiberbridge/app/${room}"
                                   "^[ \t]*#[ \t]*include[ \t]*\"(fiberbridge/app/)?(${rooms_re})/"
                                   "^[^\"]*\"(fiberbridge/app/)?([a-z]+)/.*$" 2 "${allowed}"
                                   " (room ${room} may include ${allowed_text})")
  endforeach()
  if(violations)
    message(FATAL_ERROR "The app's rooms run one way, scene <- outputs <- run <- items <- cli "
                        "(cmake/fiberbridge_layers.cmake, docs/design.md section 4):${violations}")
  endif()
endfunction()
