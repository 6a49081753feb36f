# Checks shared by the garment CLI tests, on a simulate stats JSON.
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
