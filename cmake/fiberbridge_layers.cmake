# The library graph (docs/design.md section 4), one-way:
#   core <- law <- result <- analysis ; core <- specimen <- analysis ;
#   law + specimen + result <- beam, mpm, fem (each on its own) ;
#   core <- dic (DIC frames) <- result (the virtual DIC test writes frames in dic's layouts) ; analysis + beam <- identify ; everything <- app.
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
set(FIBERBRIDGE_LAYER_beam result specimen law core)
set(FIBERBRIDGE_LAYER_mpm result specimen law core)
set(FIBERBRIDGE_LAYER_fem result specimen law core)
set(FIBERBRIDGE_LAYER_identify beam analysis result specimen law core)
set(FIBERBRIDGE_LAYER_app identify fem mpm beam dic analysis result specimen law core)

function(fiberbridge_check_layer lib)
  if(NOT DEFINED FIBERBRIDGE_LAYER_${lib})
    message(FATAL_ERROR "cmake/fiberbridge_layers.cmake: library '${lib}' has no layer rule; add "
                        "FIBERBRIDGE_LAYER_${lib} (docs/design.md section 4)")
  endif()
  set(allowed ${lib} ${FIBERBRIDGE_LAYER_${lib}})
  file(GLOB_RECURSE files ${PROJECT_SOURCE_DIR}/source/${lib}/*.cc
                          ${PROJECT_SOURCE_DIR}/source/${lib}/*.h
                          ${PROJECT_SOURCE_DIR}/include/fiberbridge/${lib}/*.h)
  set(violations "")
  foreach(f ${files})
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]fiberbridge/")
    foreach(line ${lines})
      string(REGEX REPLACE "^[^\"<]*[\"<]fiberbridge/([^/\">]+)/.*$" "\\1" dep "${line}")
      if(NOT dep IN_LIST allowed)
        file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${f})
        string(APPEND violations "\n  ${rel}: ${line}")
      endif()
    endforeach()
  endforeach()
  if(violations)
    string(REPLACE ";" " " allowed_text "${allowed}")
    message(FATAL_ERROR "Library '${lib}' may include headers of ${allowed_text} only "
                        "(cmake/fiberbridge_layers.cmake, docs/design.md section 4):${violations}")
  endif()
endfunction()
