# Exports a character with mannequin-cli, then runs the Khronos glTF-Validator
# on what was written: any error or warning fails the test.
#   -DCLI=<mannequin-cli> -DNODE=<node> -DVALIDATE=<validate_gltf.js> -DVALIDATOR=<node_modules/gltf-validator>
#   -DSOURCE=<file|default> -DOUT=<out.glb|out.gltf> [-DEXTRA="--rigged|..."]
string(REPLACE "|" ";" extra "${EXTRA}")
file(REMOVE "${OUT}")
execute_process(COMMAND "${CLI}" export "${SOURCE}" --out "${OUT}" ${extra}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
message("${out}${err}")
if(NOT status EQUAL 0 OR NOT EXISTS "${OUT}")
  message(FATAL_ERROR "export failed (exit ${status})")
endif()
execute_process(COMMAND "${NODE}" "${VALIDATE}" "${VALIDATOR}" "${OUT}"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "glTF-Validator found errors or warnings in ${OUT} (exit ${status})")
endif()
