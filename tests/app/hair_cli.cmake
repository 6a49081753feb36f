# Hair in mannequin-cli end to end: simulate a walking scene with hair and no
# cloth (stats, PLY frames whose roots sit on the posed mesh), render it, and
# groom an imported character with a built-in style and simulate it.
#   -DCLI=<mannequin-cli> -DROOTS=<mannequin_hair_roots_check> -DSCENE=<hair scene>
#   -DCHARACTER=<imported character> -DWORK=<dir> -DRENDER=ON|OFF
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake")

# --- simulate: 30 frames at 60 fps of the walk ------------------------------
run(0 "${CLI}" simulate "${SCENE}" --frames 30 --stats-json "${WORK}/stats.json" --export-dir "${WORK}/frames")
stat("${WORK}/stats.json" hair_strands strands)
stat("${WORK}/stats.json" hair_guides guides)
stat("${WORK}/stats.json" hair_points_inside_body inside)
stat("${WORK}/stats.json" hair_max_length_error length_error)
stat("${WORK}/stats.json" hair_ms_per_frame ms)
if(NOT strands EQUAL 3000 OR NOT guides GREATER 100 OR NOT inside EQUAL 0)
  message(FATAL_ERROR "stats: strands ${strands} guides ${guides} points inside ${inside}")
endif()
if(length_error GREATER 0.01)
  message(FATAL_ERROR "guide segments changed length by ${length_error}")
endif()
foreach(frame 0001 0030)
  if(NOT EXISTS "${WORK}/frames/hair_${frame}.ply")
    message(FATAL_ERROR "frame ${frame} was not exported")
  endif()
endforeach()
if(EXISTS "${WORK}/frames/hair_0031.ply")
  message(FATAL_ERROR "more frames than asked for")
endif()

# The roots of frame 30 (t = 0.5 s) are on the mesh posed at 0.5 s, not on
# the one at the start: they follow the skinned scalp.
run(0 "${CLI}" pose "${SCENE}" --time 0.5 --out "${WORK}/posed_0.5.obj")
run(0 "${CLI}" pose "${SCENE}" --time 0 --out "${WORK}/posed_0.obj")
run(0 "${ROOTS}" "${WORK}/frames/hair_0030.ply" "${WORK}/posed_0.5.obj" 0.01 3)
run(1 "${ROOTS}" "${WORK}/frames/hair_0030.ply" "${WORK}/posed_0.obj" 0.01 3)
run(0 "${ROOTS}" "${WORK}/frames/hair_0001.ply" "${WORK}/posed_0.obj" 0.01 3)

# --- render: the hair simulated to the time --------------------------------
if(RENDER)
  run(0 "${CLI}" render "${SCENE}" --time 0.5 --out "${WORK}/hair.png" --size 320x240)
  if(NOT last_output MATCHES "hair bob, 3000 strands, simulated" OR NOT EXISTS "${WORK}/hair.png")
    message(FATAL_ERROR "render did not draw the hair")
  endif()
  run(0 "${CLI}" render "${SCENE}" --time 0.5 --hair rigid --out "${WORK}/rigid.png" --size 320x240)
  if(NOT last_output MATCHES "carried by the head")
    message(FATAL_ERROR "--hair rigid was not used")
  endif()
  run(1 "${CLI}" render "${SCENE}" --hair sideways --out "${WORK}/x.png")
  if(NOT last_output MATCHES "--hair expects")
    message(FATAL_ERROR "no clear error for a bad --hair")
  endif()
endif()

# --- groom an imported character: the built-in fitted to its head ----------
run(0 "${CLI}" groom "${CHARACTER}" --style bob --strands 5000 --stats-json "${WORK}/groom.json")
stat("${WORK}/groom.json" points_inside_body inside)
stat("${WORK}/groom.json" style_scale scale)
stat("${WORK}/groom.json" strands strands)
if(NOT inside EQUAL 0 OR NOT strands EQUAL 5000 OR NOT scale GREATER 1.2)
  message(FATAL_ERROR "imported groom: points inside ${inside}, strands ${strands}, style scale ${scale}")
endif()

# ... and a scene with that character playing its clip, the style by name.
file(WRITE "${WORK}/imported.mqscene"
  "{\"format\": \"mannequin-scene\", \"version\": 1, \"character\": \"${CHARACTER}\",\n"
  " \"hair\": {\"style\": \"long_straight\", \"strands\": 3000}}\n")
run(0 "${CLI}" simulate "${WORK}/imported.mqscene" --frames 20 --stats-json "${WORK}/imported.json")
stat("${WORK}/imported.json" hair_points_inside_body inside)
stat("${WORK}/imported.json" hair_max_length_error length_error)
if(NOT inside EQUAL 0 OR length_error GREATER 0.02)
  message(FATAL_ERROR "imported character's hair: points inside ${inside}, length error ${length_error}")
endif()

# ... and the same as adaptive wisps: fewer guides simulated, none inside the
# body, every guide (simulated or following) at its length.
run(0 "${CLI}" simulate "${WORK}/imported.mqscene" --frames 60 --hair-wisps adaptive
    --stats-json "${WORK}/imported_wisps.json")
stat("${WORK}/imported_wisps.json" hair_points_inside_body inside)
stat("${WORK}/imported_wisps.json" hair_max_length_error length_error)
stat("${WORK}/imported_wisps.json" hair_guides guides)
stat("${WORK}/imported_wisps.json" hair_simulated_guides_min fewest)
stat("${WORK}/imported_wisps.json" hair_adaptive_wisps adaptive)
if(NOT adaptive OR NOT inside EQUAL 0 OR length_error GREATER 0.02 OR NOT fewest LESS guides)
  message(FATAL_ERROR "imported character's adaptive wisps: on ${adaptive}, points inside ${inside}, "
                      "length error ${length_error}, fewest guides simulated ${fewest} of ${guides}")
endif()
