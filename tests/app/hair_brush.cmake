# Grooming brushes from mannequin-cli: cut strokes make a bob of the long
# hair on the default mannequin and on an imported character, the strokes
# are saved in the scene and replayed by every command that grows the hair.
#   -DCLI=<mannequin-cli> -DCHARACTER=<imported character> -DWORK=<dir>
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake")

# A positive decimal in metres as whole millimetres (math() takes integers).
function(to_mm value out)
  if(NOT value MATCHES "^([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "not a positive decimal: ${value}")
  endif()
  string(SUBSTRING "${CMAKE_MATCH_3}000" 0 3 fraction)
  math(EXPR mm "${CMAKE_MATCH_1} * 1000 + ${fraction}")  # a leading 0 is still decimal in math()
  set(${out} ${mm} PARENT_SCOPE)
endfunction()

# Cuts the hair of SCENE at height Y (world metres, rest pose) behind the
# head (z = BACK, x from -HALF_WIDTH to HALF_WIDTH) and along both sides
# (x = SIDE from z = BACK to FRONT, mirrored), with a brush of RADIUS; checks that the hair's lowest
# point rose above Y - RADIUS, that the strokes were saved and that the saved
# scene grows the same hair again. The points come from each character's
# uncut groom (groom --stats-json): its bounds and head size.
function(cut_to_bob name scene y back front half_width side radius)
  run(0 "${CLI}" groom "${scene}" --stats-json "${WORK}/${name}_long.json")
  stat("${WORK}/${name}_long.json" "bbox_min;1" low)
  run(0 "${CLI}" groom "${scene}" --brush cut --at -${half_width},${y},${back} --to ${half_width},${y},${back}
      --radius ${radius} --save-as "${WORK}/${name}_back.mqscene")
  run(0 "${CLI}" groom "${WORK}/${name}_back.mqscene" --brush cut --at ${side},${y},${back} --to ${side},${y},${front}
      --radius ${radius} --mirror --save-as "${WORK}/${name}_bob.mqscene" --stats-json "${WORK}/${name}_bob.json")
  if(NOT last_output MATCHES "2 brush strokes; points inside the body: 0")
    message(FATAL_ERROR "${name}: the cut hair should hold two strokes and stay out of the body")
  endif()
  stat("${WORK}/${name}_bob.json" "bbox_min;1" bob_low)
  message("${name}: the hair's lowest point rose from ${low} to ${bob_low} m (cut at ${y} m)")
  to_mm("${bob_low}" bob_mm)
  to_mm("${floor}" floor_mm)
  if(bob_mm LESS floor_mm)
    message(FATAL_ERROR "${name}: after the cut the hair still reaches ${bob_low} m, below ${floor} m")
  endif()
  # The saved scene grows the same hair.
  run(0 "${CLI}" groom "${WORK}/${name}_bob.mqscene" --stats-json "${WORK}/${name}_again.json")
  stat("${WORK}/${name}_again.json" "bbox_min;1" again_low)
  stat("${WORK}/${name}_again.json" "strokes" strokes)
  if(NOT strokes EQUAL 2 OR NOT again_low STREQUAL bob_low)
    message(FATAL_ERROR "${name}: reopened, the scene grows other hair (${strokes} strokes, lowest ${again_low} vs ${bob_low})")
  endif()
endfunction()

# FLOOR: the lowest the cut hair may reach (the cut's height less a brush radius).
set(floor 1.30)
cut_to_bob(mannequin default 1.39 -0.235 0.2 0.3 0.198 0.089)
set(floor 0.84)
cut_to_bob(imported "${CHARACTER}" 0.98 -0.3 0.3 0.45 0.31 0.14)
# Painted density: a tenth of the hair where painted, all of it elsewhere.
run(0 "${CLI}" groom default --stats-json "${WORK}/full.json")
run(0 "${CLI}" groom default --brush paint_density --at -0.1,1.7,-0.08 --to 0.1,1.7,-0.08 --radius 0.06 --value 0.1
    --strength 1 --stats-json "${WORK}/thin.json")
stat("${WORK}/full.json" strands full)
stat("${WORK}/thin.json" strands thin)
math(EXPR most "${full} * 95 / 100")
math(EXPR least "${full} / 2")
message("painted density: ${full} -> ${thin} strands")
if(NOT thin LESS most OR NOT thin GREATER least)
  message(FATAL_ERROR "painting a tenth of the hair on the back of the head should keep between half and 95 % of it")
endif()
# Simulating the cut hair replays the strokes too.
run(0 "${CLI}" simulate "${WORK}/mannequin_bob.mqscene" --frames 5 --stats-json "${WORK}/simulated.json")
stat("${WORK}/simulated.json" "hair_bbox_min;1" simulated_low)
stat("${WORK}/mannequin_bob.json" "bbox_min;1" bob_low)
message("simulated cut hair: lowest point ${simulated_low} m (groomed ${bob_low} m)")
# Painted colour: a blond streak along the parting (melanin 0.15 over the
# style's 1.3), saved and grown again the same.
run(0 "${CLI}" groom default --brush paint_melanin --at 0,1.75,0.04 --to 0,1.745,-0.06 --radius 0.025 --value 0.15
    --strength 1 --save-as "${WORK}/streak.mqscene" --stats-json "${WORK}/streak.json")
stat("${WORK}/streak.json" "pigments;painted_strands" painted)
stat("${WORK}/streak.json" "pigments;melanin;0" lightest)
stat("${WORK}/streak.json" "pigments;melanin;1" darkest)
message("painted melanin: ${painted} strands, melanin ${lightest} to ${darkest}")
if(painted LESS 1000 OR lightest GREATER 0.16 OR darkest LESS 1.29 OR darkest GREATER 1.31)
  message(FATAL_ERROR "the streak should make over 1,000 strands blond (melanin down to 0.15) and leave the rest at 1.3")
endif()
run(0 "${CLI}" groom "${WORK}/streak.mqscene" --stats-json "${WORK}/streak_again.json")
stat("${WORK}/streak_again.json" "pigments;painted_strands" again)
if(NOT again EQUAL painted)
  message(FATAL_ERROR "reopened, the streak colours ${again} strands, not ${painted}")
endif()
