# The layer check: fails when a source file includes what its layer may not
# see (ARCHITECTURE.md, "Layers"). Reads #include lines only, so it sees a
# leak even where linking would not catch it (a header-only use).
#   cmake -DMANNEQUIN_SOURCE_DIR=<repository> -P cmake/layer_check.cmake
# Prints file:line for each offending include and exits non-zero.
cmake_minimum_required(VERSION 3.25)

if(NOT MANNEQUIN_SOURCE_DIR)
  get_filename_component(MANNEQUIN_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
endif()

# What each layer may not include, by name; each name's regular expression
# is matched against the included path (between the quotes or brackets).
set(pattern_sim "^sim/")
set(pattern_render "^render/")
set(pattern_ui "^ui/")
set(pattern_app "^app/")
set(pattern_Qt "^Q[A-Za-z]")  # <QWidget>, <QtCore/...>, <QVTKOpenGLNativeWidget.h>
set(pattern_VTK "^vtk")
set(forbidden_core sim render ui app Qt VTK)
set(forbidden_sim render ui app Qt VTK)
set(forbidden_render sim ui app Qt)
set(forbidden_ui app)
set(forbidden_app VTK)

set(include_line "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"]")
set(violations 0)
foreach(layer core sim render ui app)
  file(GLOB_RECURSE sources LIST_DIRECTORIES false
       "${MANNEQUIN_SOURCE_DIR}/${layer}/*.h" "${MANNEQUIN_SOURCE_DIR}/${layer}/*.hpp"
       "${MANNEQUIN_SOURCE_DIR}/${layer}/*.cpp")
  list(SORT sources)
  foreach(source IN LISTS sources)
    # A CMake list splits at semicolons and keeps brackets and backslashes
    # together, so those characters go before splitting into lines.
    file(READ "${source}" text)
    string(REGEX REPLACE "[];[\\]" " " text "${text}")
    string(REPLACE "\n" ";" lines "${text}")
    set(line_number 0)
    foreach(line IN LISTS lines)
      math(EXPR line_number "${line_number} + 1")
      if(NOT line MATCHES "${include_line}")
        continue()
      endif()
      set(included "${CMAKE_MATCH_1}")
      foreach(forbidden IN LISTS forbidden_${layer})
        if(included MATCHES "${pattern_${forbidden}}")
          file(RELATIVE_PATH relative "${MANNEQUIN_SOURCE_DIR}" "${source}")
          message("${relative}:${line_number}: ${layer}/ may not include ${forbidden} (${included})")
          math(EXPR violations "${violations} + 1")
          break()
        endif()
      endforeach()
    endforeach()
  endforeach()
endforeach()

if(violations GREATER 0)
  message(FATAL_ERROR "layer check: ${violations} include(s) cross a layer boundary (see ARCHITECTURE.md)")
endif()
message(STATUS "layer check: every include respects the layers")
