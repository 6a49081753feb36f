# Steps of the CLI test scripts (include()d).
#   run(EXIT command...): runs it, prints it with its output, fails on another
#     exit code; last_output holds its standard output and error.
#   stat(FILE KEY OUT): the value at KEY in the JSON file (a list of keys for
#     a nested value: "bbox_min;1"); fails when it is missing.
function(run expect_exit)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  message("${ARGN}\n -> exit ${code}\n${out}${err}")
  if(NOT code EQUAL expect_exit)
    message(FATAL_ERROR "expected exit ${expect_exit}, got ${code}")
  endif()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()

function(stat file key out)
  file(READ "${file}" json)
  string(JSON value ERROR_VARIABLE missing GET "${json}" ${key})
  if(missing)
    message(FATAL_ERROR "${file} has no key ${key}")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()
