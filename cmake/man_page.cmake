# Writes a program's man page, gzipped, from its --help (help2man):
#   cmake -DHELP2MAN=<help2man> -DPROGRAM=<built program> -DVERSION=<x.y.z> -DNAME=<one-line summary>
#         -DSEE_ALSO=<other program> -DOUT=<dir>/<program>.1.gz [-DCOMMANDS=ON] -P cmake/man_page.cmake
# COMMANDS=ON (mannequin-cli): --help is shown as written, and each command it
# lists gets a subsection of COMMANDS with its own `<command> --help`.
foreach(var HELP2MAN PROGRAM VERSION NAME SEE_ALSO OUT)
  if(NOT ${var})
    message(FATAL_ERROR "man_page.cmake needs -D${var}=...")
  endif()
endforeach()
get_filename_component(program_dir "${PROGRAM}" DIRECTORY)
get_filename_component(program_name "${PROGRAM}" NAME)
string(REGEX REPLACE "\\.gz$" "" page "${OUT}")

# Help text as roff lines shown as written: backslashes escaped, no line read as a request.
function(as_roff text out_var)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out_var} ".nf\n${text}.fi\n" PARENT_SCOPE)
endfunction()

function(help_of out_var)  # ARGN: the arguments before --help
  execute_process(COMMAND "${PROGRAM}" ${ARGN} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${program_name} ${ARGN} --help failed (${status})")
  endif()
  set(${out_var} "${help}" PARENT_SCOPE)
endfunction()

set(include_file "${page}.h2m")
file(WRITE "${include_file}" "[SEE ALSO]\n.BR ${SEE_ALSO} (1)\n")
if(COMMANDS)
  help_of(usage)
  as_roff("${usage}" roff)
  file(APPEND "${include_file}" "[=DESCRIPTION]\n${roff}[COMMANDS]\n")
  string(REGEX MATCHALL "\n  [a-z][a-z-]* " command_lines "${usage}")
  foreach(line IN LISTS command_lines)
    string(STRIP "${line}" command)
    help_of(help ${command})
    as_roff("${help}" roff)
    file(APPEND "${include_file}" ".SS ${command}\n${roff}")
  endforeach()
endif()

# Run by its name alone, so the page shows `mannequin`, not the build tree's path.
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env "PATH=${program_dir}:$ENV{PATH}"
          "${HELP2MAN}" --no-info --section=1 "--version-string=${VERSION}" "--name=${NAME}"
          "--include=${include_file}" "--output=${page}" "${program_name}"
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed on ${program_name} (${status})")
endif()
# -n: no time stamp in the archive, the same bytes for the same page.
execute_process(COMMAND gzip -9 -n -f "${page}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gzip failed on ${page} (${status})")
endif()
