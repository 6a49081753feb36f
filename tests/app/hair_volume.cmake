# Hair against hair from mannequin-cli: the head-turn example with its
# dynamics (volume 0.5, friction 0.2) and with them turned off by the
# options; the stats report them and count the guide segments closer than
# half their spacing, fewer with the interaction on.
#   -DCLI=<mannequin-cli> -DSCENE=<hair_head_turn.json> -DWORK=<dir>
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake")

run(0 "${CLI}" simulate "${SCENE}" --frames 30 --hair-crossings --stats-json "${WORK}/on.json")
run(0 "${CLI}" simulate "${SCENE}" --frames 30 --hair-crossings --hair-volume 0 --hair-friction 0
    --stats-json "${WORK}/off.json")
stat("${WORK}/on.json" hair_volume volume)
stat("${WORK}/on.json" hair_friction friction)
stat("${WORK}/off.json" hair_volume volume_off)
if(volume LESS 0.49 OR volume GREATER 0.51)
  message(FATAL_ERROR "the scene's volume 0.5 was read as ${volume}")
endif()
if(friction LESS 0.19 OR friction GREATER 0.21 OR volume_off GREATER 0)
  message(FATAL_ERROR "friction ${friction}, volume with --hair-volume 0: ${volume_off}")
endif()
foreach(side on off)
  stat("${WORK}/${side}.json" hair_close_guide_pairs_mean ${side}_mean)
  stat("${WORK}/${side}.json" hair_close_guide_pairs_groomed ${side}_groomed)
  stat("${WORK}/${side}.json" hair_points_inside_body ${side}_inside)
  stat("${WORK}/${side}.json" hair_max_length_error ${side}_length)
  if(NOT ${side}_inside EQUAL 0 OR ${side}_length GREATER 0.1)
    message(FATAL_ERROR "${side}: ${${side}_inside} points inside the body, length error ${${side}_length}")
  endif()
endforeach()
message("close guide segment pairs a frame: groomed ${on_groomed}, moving ${off_mean} without, ${on_mean} with")
# The turn packs hair against hair: more close pairs than the groom has; the
# interaction takes back a good part of that excess.
if(NOT off_mean GREATER off_groomed OR NOT on_mean LESS off_mean)
  message(FATAL_ERROR "expected groomed < with interaction < without")
endif()
