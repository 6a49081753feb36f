# mannequin-cli simulate on the trousers walk: sewn on the rest pose, then
# walking; the legs must stay inside the trouser legs.
#   -DCLI=<exe> -DSCENE=<scene.json> -DWORK=<dir> -DFRAMES=<n> -DMAX_PENETRATING=<n>
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CLI}" simulate "${SCENE}" --frames ${FRAMES} --stats-json "${WORK}/stats.json"
  RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
message("exit ${exit_code}\nstdout: ${out}\nstderr: ${err}")
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "simulate failed")
endif()
file(READ "${WORK}/stats.json" stats)
message("${stats}")
string(JSON welded GET "${stats}" garments 0 welded)
string(JSON penetrating GET "${stats}" penetrating_vertices)
string(JSON stretch GET "${stats}" final_max_stretch)
string(JSON min_y GET "${stats}" bbox_min 1)
string(JSON max_y GET "${stats}" bbox_max 1)
if(NOT welded)
  message(FATAL_ERROR "the trousers' seams were not welded")
endif()
# A leg that swung out of its trouser leg leaves the cloth inside it when it
# swings back (134 vertices at frame 30 before the fix).
if(penetrating GREATER ${MAX_PENETRATING})
  message(FATAL_ERROR "${penetrating} cloth vertices inside the body (at most ${MAX_PENETRATING})")
endif()
if(stretch GREATER 1.101)
  message(FATAL_ERROR "final stretch ${stretch} beyond the 1.1 limit")
endif()
# On the hips of the 1.8 m mannequin, down to the ankles.
if(max_y LESS 0.9 OR max_y GREATER 1.15 OR min_y GREATER 0.35)
  message(FATAL_ERROR "the trousers are not on the hips and legs: y ${min_y} .. ${max_y}")
endif()
