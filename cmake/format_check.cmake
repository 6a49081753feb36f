# The format check: fails when a source file differs from what clang-format
# makes of it with the house .clang-format (ARCHITECTURE.md, "Formatting").
#   cmake -DMANNEQUIN_SOURCE_DIR=<repository> [-DCLANG_FORMAT=<program>] -P cmake/format_check.cmake
# Prints each file that needs formatting and exits non-zero.
cmake_minimum_required(VERSION 3.25)

if(NOT MANNEQUIN_SOURCE_DIR)
  get_filename_component(MANNEQUIN_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
endif()
if(NOT CLANG_FORMAT)
  # The version the tree was formatted with: another version formats a few constructs differently.
  find_program(CLANG_FORMAT NAMES clang-format-14 REQUIRED)
endif()

set(sources "")
foreach(folder core sim render ui app tests)
  file(GLOB_RECURSE found LIST_DIRECTORIES false
       "${MANNEQUIN_SOURCE_DIR}/${folder}/*.h" "${MANNEQUIN_SOURCE_DIR}/${folder}/*.cpp")
  list(APPEND sources ${found})
endforeach()
list(FILTER sources EXCLUDE REGEX "/tests/fuzz/regressions/")

execute_process(COMMAND "${CLANG_FORMAT}" --dry-run --Werror ${sources}
                WORKING_DIRECTORY "${MANNEQUIN_SOURCE_DIR}" RESULT_VARIABLE status ERROR_VARIABLE problems)
if(NOT status EQUAL 0)
  string(REGEX MATCHALL "[^\n]+: error: code should be clang-formatted" lines "${problems}")
  set(files "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE ":[0-9]+:[0-9]+: error: code should be clang-formatted" "" file "${line}")
    list(APPEND files "${file}")
  endforeach()
  list(REMOVE_DUPLICATES files)
  list(JOIN files "\n  " shown)
  message(FATAL_ERROR "not formatted (run clang-format-14 -i on them):\n  ${shown}")
endif()
list(LENGTH sources count)
message(STATUS "format check: ${count} files formatted")
