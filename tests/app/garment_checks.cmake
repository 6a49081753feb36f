# Checks shared by the garment CLI tests, on a simulate stats JSON.
# simulate_scene(OUT_JSON TIMEOUT ARGS...): runs `CLI simulate SCENE ARGS...
# --stats-json OUT_JSON`, prints its output, fails when it fails, and sets
# `stats` in the caller to the JSON.
function(simulate_scene out_json timeout)
  execute_process(COMMAND "${CLI}" simulate "${SCENE}" ${ARGN} --stats-json "${out_json}"
    RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${timeout})
  string(JOIN " " args ${ARGN})
  message("simulate ${args}: exit ${exit_code}\nstdout: ${out}\nstderr: ${err}")
  if(NOT exit_code EQUAL 0)
    message(FATAL_ERROR "simulate ${args} failed")
  endif()
  file(READ "${out_json}" json)
  set(stats "${json}" PARENT_SCOPE)
endfunction()

# check_body_and_stretch(STATS KEY MAX WHEN): the body holds at most MAX cloth
# vertices by the stats' KEY (penetrating_vertices: at the last frame,
# max_penetrating_vertices: in any frame; WHEN says which in the message), and
# the final stretch is within the 1.1 elongation limit (with rounding).
function(check_body_and_stretch stats key max when)
  string(JSON penetrating GET "${stats}" ${key})
  string(JSON stretch GET "${stats}" final_max_stretch)
  if(penetrating GREATER ${max})
    message(FATAL_ERROR "${penetrating} cloth vertices inside the body${when} (at most ${max})")
  endif()
  if(stretch GREATER 1.101)
    message(FATAL_ERROR "final stretch ${stretch} beyond the 1.1 limit")
  endif()
endfunction()
