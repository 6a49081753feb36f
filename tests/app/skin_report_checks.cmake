# skin-report on the default mannequin and CesiumMan: the skinning methods
# against the research brief's targets (the ones they meet today).
#   -DCLI=<mannequin-cli> -DCESIUM=<CesiumMan.gltf> -DWORK=<dir>
file(MAKE_DIRECTORY "${WORK}")

function(report file method out)
  execute_process(COMMAND "${CLI}" skin-report "${file}" --skinning ${method} --json ${ARGN}
    RESULT_VARIABLE code OUTPUT_VARIABLE json ERROR_VARIABLE err TIMEOUT 600)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "skin-report ${file} --skinning ${method} failed (${code}): ${err}")
  endif()
  set(${out} "${json}" PARENT_SCOPE)
endfunction()

# pose_value(<json> <pose name> <field> <out>)
function(pose_value json pose field out)
  string(JSON count LENGTH "${json}" poses)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" poses ${i} pose)
    if(name STREQUAL pose)
      string(JSON value GET "${json}" poses ${i} ${field})
      set(${out} "${value}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "no pose '${pose}' in the report")
endfunction()

function(expect_compare json label pose field op bound)
  pose_value("${json}" "${pose}" ${field} value)
  message("${label} ${pose} ${field} = ${value} (expected ${op} ${bound})")
  if(op STREQUAL ">=")
    if(value LESS bound)
      message(FATAL_ERROR "${label}: ${pose} ${field} ${value} is below ${bound}")
    endif()
  elseif(value GREATER bound)
    message(FATAL_ERROR "${label}: ${pose} ${field} ${value} is above ${bound}")
  endif()
endfunction()

report(default lbs lbs --no-clips)
report(default dqs dqs --no-clips)
report(default cones cones --no-clips)

# LBS collapses (the baseline the others are measured against).
expect_compare("${lbs}" lbs "elbow 120" thickness "<=" 0.6)
expect_compare("${lbs}" lbs "wrist twist 180" twist_section "<=" 0.1)
foreach(method dqs cones)
  set(json "${${method}}")
  string(JSON rest GET "${json}" rest_error)
  if(rest GREATER 1e-5)
    message(FATAL_ERROR "${method}: the rest pose is ${rest} of the bounding box off the rest mesh")
  endif()
  foreach(pose "elbow 90" "elbow 120" "elbow 150" "knee 90" "knee 120" "knee 150")
    expect_compare("${json}" ${method} "${pose}" thickness ">=" 0.95)
  endforeach()
  foreach(pose "wrist twist 180" "forearm twist 180")
    expect_compare("${json}" ${method} "${pose}" twist_section ">=" 0.9)
  endforeach()
endforeach()

# The creases: the knee and elbow folds no longer cross as DQS's do.
expect_compare("${cones}" cones "knee 120" intersections "<=" 10)
pose_value("${dqs}" "elbow 150" intersections dqs_elbow)
expect_compare("${cones}" cones "elbow 150" intersections "<=" ${dqs_elbow})
expect_compare("${cones}" cones "elbow 120" local_volume ">=" 0.95)

# The walk with creases is no worse than with dual quaternions.
report(default dqs dqs_walk --no-poses)
report(default cones cones_walk --no-poses)
string(JSON dqs_worst GET "${dqs_walk}" clips 0 worst_intersections)
string(JSON cones_worst GET "${cones_walk}" clips 0 worst_intersections)
message("walk worst frame: dqs ${dqs_worst}, cones ${cones_worst}")
if(cones_worst GREATER dqs_worst)
  message(FATAL_ERROR "cones cross more than dqs on the walk: ${cones_worst} > ${dqs_worst}")
endif()

# An imported humanoid (other bone names, its own weights).
report("${CESIUM}" cones cesium --no-clips)
expect_compare("${cesium}" CesiumMan "elbow 120" thickness ">=" 0.95)
expect_compare("${cesium}" CesiumMan "forearm twist 180" twist_section ">=" 0.9)
expect_compare("${cesium}" CesiumMan "knee 120" intersections "<=" 27)

# M6: the skin's distance to the mannequin's posed implicit body. LBS sinks
# the elbow into it (the brief's baseline, 12.7 mm); DQS keeps it closer.
expect_compare("${lbs}" lbs "elbow 120" body_deviation_rms_mm ">=" 10.0)
expect_compare("${dqs}" dqs "elbow 120" body_deviation_rms_mm "<=" 11.5)
pose_value("${lbs}" "elbow 120" body_deviation_mean_mm lbsMean)
if(lbsMean GREATER -5.0)
  message(FATAL_ERROR "lbs elbow 120: the skin should sink into the body (mean ${lbsMean} mm)")
endif()
# An imported skin has no implicit body: M6 is not measured.
pose_value("${cesium}" "elbow 120" body_deviation_rms_mm cesiumDeviation)
if(NOT (cesiumDeviation STREQUAL "" OR cesiumDeviation STREQUAL "null"))  # JSON null
  message(FATAL_ERROR "CesiumMan has no implicit body, yet M6 = ${cesiumDeviation}")
endif()

# Helper bones under plain LBS (the exportable path): the research brief's
# targets at 120 degrees and for the 180-degree wrist twist, on both characters.
report(default lbs helpers --no-clips --helper-bones)
report("${CESIUM}" lbs cesiumHelpers --no-clips --helper-bones)
foreach(pose "elbow 120" "knee 120")
  expect_compare("${helpers}" "lbs + helper bones" "${pose}" thickness ">=" 0.85)
  expect_compare("${cesiumHelpers}" "CesiumMan lbs + helper bones" "${pose}" thickness ">=" 0.85)
endforeach()
expect_compare("${helpers}" "lbs + helper bones" "wrist twist 180" twist_section ">=" 0.6)
# The elbow's two stages keep a forearm twisted half a turn at 0.75 (one
# half-angle bone kept 0.5); they fold the inner elbow a little more (the
# brief's LBS+H target for crossings at 120 degrees is <= 100).
foreach(name helpers cesiumHelpers)
  expect_compare("${${name}}" "${name}" "forearm twist 180" twist_section ">=" 0.7)
endforeach()
expect_compare("${helpers}" "lbs + helper bones" "elbow 120" intersections "<=" 50)
expect_compare("${helpers}" "lbs + helper bones" "hip 90" local_volume ">=" 0.8)

# Regenerated weights with helper bones under plain LBS (the exportable path):
# the research brief's LBS+H targets for the walk and arm_raise crossings.
report(default lbs helpers_clips --no-poses --helper-bones)
report(default lbs regenerated --helper-bones --regenerate-weights)
string(JSON rest GET "${regenerated}" rest_error)
if(rest GREATER 1e-5)
  message(FATAL_ERROR "regenerated weights: the rest pose is ${rest} of the bounding box off the rest mesh")
endif()
foreach(pose "elbow 120" "knee 120")
  expect_compare("${regenerated}" "regenerated + helper bones" "${pose}" thickness ">=" 0.85)
endforeach()
expect_compare("${regenerated}" "regenerated + helper bones" "elbow 120" intersections "<=" 10)
expect_compare("${regenerated}" "regenerated + helper bones" "hip 90" intersections "<=" 20)
foreach(clip 0 1)
  string(JSON name GET "${regenerated}" clips ${clip} clip)
  string(JSON worst GET "${regenerated}" clips ${clip} worst_intersections)
  string(JSON before GET "${helpers_clips}" clips ${clip} worst_intersections)
  message("regenerated + helper bones, clip ${name}: worst ${worst} crossing pairs (file weights: ${before})")
  if(worst GREATER 40)
    message(FATAL_ERROR "regenerated weights: clip ${name} crosses itself in ${worst} pairs (target 40)")
  endif()
  if(clip EQUAL 0 AND NOT worst LESS before)
    message(FATAL_ERROR "regenerated weights: the walk crosses itself no less than with the file's weights")
  endif()
endforeach()
# The same on CesiumMan, whose weights the regeneration was not tuned on:
# fewer crossings over its clip than with its own weights and helper bones.
report("${CESIUM}" lbs cesiumFileClip --no-poses --helper-bones)
report("${CESIUM}" lbs cesiumRegenerated --no-poses --helper-bones --regenerate-weights)
foreach(field worst_intersections mean_intersections)
  string(JSON regenerated GET "${cesiumRegenerated}" clips 0 ${field})
  string(JSON file GET "${cesiumFileClip}" clips 0 ${field})
  message("CesiumMan + helper bones, clip ${field}: ${regenerated} regenerated, ${file} with its own weights")
  if(NOT regenerated LESS file)
    message(FATAL_ERROR "CesiumMan: regenerated weights do not lower the clip's ${field} (${regenerated} against ${file})")
  endif()
endforeach()
string(JSON mean GET "${cesiumRegenerated}" clips 0 mean_intersections)
if(mean GREATER 10)
  message(FATAL_ERROR "CesiumMan with regenerated weights: ${mean} crossing pairs a frame on average (target 10)")
endif()
