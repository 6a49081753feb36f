# Runs one mannequin-cli command and checks its exit code and output.
#   -DCLI=<exe> -DARGS="a;b;c" -DEXPECT_EXIT=<n> [-DEXPECT_OUTPUT=<regex>] [-DEXPECT_FILE=<path>]
#   [-DIMAGE_CHECK=<mannequin_image_check> -DIMAGE_BASELINE=<name>]: the file, a PNG, matches that baseline
set(arg_list ${ARGS})
if(EXPECT_FILE)
  file(REMOVE "${EXPECT_FILE}")
endif()
execute_process(COMMAND "${CLI}" ${arg_list}
  RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
message("exit ${exit_code}\nstdout: ${out}\nstderr: ${err}")
if(NOT exit_code EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "expected exit code ${EXPECT_EXIT}, got ${exit_code}")
endif()
if(EXPECT_OUTPUT AND NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECT_OUTPUT}'")
endif()
if(EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
  message(FATAL_ERROR "${EXPECT_FILE} was not written")
endif()
if(IMAGE_BASELINE)
  execute_process(COMMAND "${IMAGE_CHECK}" "${EXPECT_FILE}" "${IMAGE_BASELINE}" RESULT_VARIABLE image_status
                  OUTPUT_VARIABLE image_out ERROR_VARIABLE image_err)
  if(NOT image_status EQUAL 0)
    message(FATAL_ERROR "${image_out}${image_err}")
  endif()
  message("${image_out}")
endif()
