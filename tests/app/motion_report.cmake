# mannequin-cli and BVH motions: the match report on stderr (stdout's JSON
# stays valid), --in-place keeps the pelvis over its start, a scene
# document's motion reports too, and bad BVH or map files name the file.
# -DCLI -DASSETS -DSOURCE_DIR -DWORK
set(cmu "${ASSETS}/motion/cmu_01_01.bvh")
file(MAKE_DIRECTORY "${WORK}")

function(expect_match text regex what)
  if(NOT "${text}" MATCHES "${regex}")
    message(FATAL_ERROR "${what}: '${text}' does not match '${regex}'")
  endif()
endfunction()

# Runs the CLI; fails unless it exits with `code`. Sets out and err.
function(run code)
  execute_process(COMMAND "${CLI}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL code)
    message(FATAL_ERROR "mannequin-cli ${ARGN}: exit ${rc}, expected ${code}\n${o}\n${e}")
  endif()
  set(out "${o}" PARENT_SCOPE)
  set(err "${e}" PARENT_SCOPE)
endfunction()

# The pelvis's world position "x;y;z" in a --joints-out file.
function(pelvis_of joints_file var)
  file(READ "${joints_file}" json)
  string(JSON count LENGTH "${json}" bones)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" bones ${i} name)
    if(name STREQUAL "pelvis")
      string(JSON x GET "${json}" bones ${i} head 0)
      string(JSON y GET "${json}" bones ${i} head 1)
      string(JSON z GET "${json}" bones ${i} head 2)
      set(${var} "${x};${y};${z}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "no pelvis in ${joints_file}")
endfunction()

# The report, by names then roles; stdout keeps its one "wrote" line.
run(0 pose default --motion "${cmu}" --time 0 --out "${WORK}/cmu0.obj" --joints-out "${WORK}/walk0.json")
expect_match("${err}" "motion [^\n]*cmu_01_01.bvh: matched 19 of 31 bones; unmatched: LHipJoint, LeftToeBase, RHipJoint, RightToeBase, LowerBack, Neck1, LeftFingerBase, LFingers, LThumb, RightFingerBase, RFingers, RThumb; not driven on the character: toes_l, toes_r"
             "report without a map")
expect_match("${out}" "^wrote [^\n]*clip 'cmu_01_01'" "pose's own line")
run(0 pose default --motion "${cmu}" --time 5 --out "${WORK}/cmu5.obj" --joints-out "${WORK}/walk5.json")

# Through the shipped map: its 21 pairs, all the character's bones driven.
run(0 pose default --motion "${cmu}" --map "${SOURCE_DIR}/resources/motion_maps/cmu_to_default.txt" --time 0
    --out "${WORK}/cmu_map.obj")
expect_match("${err}" "matched 21 of 31 bones; unmatched: LHipJoint, RHipJoint, Spine, Neck1, LeftFingerBase, LFingers, LThumb, RightFingerBase, RFingers, RThumb\n"
             "report with the map")

# --in-place: the pelvis stays over its start; without it the walk travels.
run(0 pose default --motion "${cmu}" --in-place --time 0 --out "${WORK}/still0.obj" --joints-out "${WORK}/still0.json")
run(0 pose default --motion "${cmu}" --in-place --time 5 --out "${WORK}/still5.obj" --joints-out "${WORK}/still5.json")
# The root's horizontal translation is dropped exactly, so the numbers match
# to the last digit.
pelvis_of("${WORK}/walk0.json" walk0)
pelvis_of("${WORK}/walk5.json" walk5)
pelvis_of("${WORK}/still0.json" still0)
pelvis_of("${WORK}/still5.json" still5)
list(GET walk0 0 x0)
list(GET walk5 0 x5)
if(x0 STREQUAL x5)
  message(FATAL_ERROR "without --in-place the pelvis should travel: x ${x0} at 0 s and at 5 s")
endif()
foreach(axis 0 2)
  list(GET still0 ${axis} a)
  list(GET still5 ${axis} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "with --in-place the pelvis moved on axis ${axis}: ${a} -> ${b}")
  endif()
endforeach()
list(GET still0 1 y0)
list(GET still5 1 y5)
if(y0 STREQUAL y5)
  message(FATAL_ERROR "with --in-place the pelvis should still bob: y ${y0} at 0 s and at 5 s")
endif()
run(1 pose default --in-place --time 0 --out "${WORK}/never.obj")
expect_match("${err}" "--in-place needs --motion" "--in-place alone")

# A scene document's motion reports on stderr; info --json stays valid JSON.
file(WRITE "${WORK}/walk.mqscene" "{\"format\": \"mannequin-scene\", \"version\": 1, \"character\": \"default\",
  \"motion\": {\"file\": \"${cmu}\", \"inPlace\": true}}")
run(0 info "${WORK}/walk.mqscene" --json)
expect_match("${err}" "motion [^\n]*cmu_01_01.bvh: matched 19 of 31 bones" "report for a scene's motion")
string(JSON clips LENGTH "${out}" clips)
if(NOT clips EQUAL 4)
  message(FATAL_ERROR "info --json of the scene: expected the mannequin's three clips and the motion, got ${clips}")
endif()

# Bad files: exit 1, the message names the file and the line.
file(WRITE "${WORK}/bad.map" "Hips pelvis\nLeftArm\n")
run(1 pose default --motion "${cmu}" --map "${WORK}/bad.map" --time 0 --out "${WORK}/never.obj")
expect_match("${err}" "${WORK}/bad.map.*line 2: expected 'bvh_joint_name target_bone_name'" "bad map")
file(WRITE "${WORK}/broken.bvh" "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 x\n")
run(1 pose default --motion "${WORK}/broken.bvh" --time 0 --out "${WORK}/never.obj")
expect_match("${err}" "${WORK}/broken.bvh.*line 4: expected a number" "broken BVH")
if(EXISTS "${WORK}/never.obj")
  message(FATAL_ERROR "a failed pose wrote its output")
endif()

# The help says how.
run(0 pose --help)
expect_match("${out}" "--in-place.*matched N of M bones" "pose --help")
