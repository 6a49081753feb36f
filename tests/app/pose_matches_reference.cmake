# Runs `mannequin-cli pose` and compares the OBJ with a reference pose.
# -DCLI -DDIFF -DSOURCE -DTIME -DCLIP -DOUT -DREFERENCE -DTOLERANCE
execute_process(COMMAND "${CLI}" pose "${SOURCE}" --time "${TIME}" --clip "${CLIP}" --out "${OUT}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mannequin-cli pose failed (${rc}): ${out}${err}")
endif()
execute_process(COMMAND "${DIFF}" "${OUT}" "${REFERENCE}" "${TOLERANCE}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "posed mesh differs from ${REFERENCE}: ${out}${err}")
endif()
