# `mannequin-cli info --json` reports the MANIFEST counts; bad files give
# exit code 1 and a one-line message naming the file.
# -DCLI -DASSETS -DWORK [-DSOURCE_DIR]
if(NOT SOURCE_DIR)
  get_filename_component(SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()
function(info_json file out_var)
  execute_process(COMMAND "${CLI}" info "${file}" --json RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "info ${file} failed (${rc}): ${err}")
  endif()
  set(${out_var} "${json}" PARENT_SCOPE)
endfunction()

function(expect actual expected what)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: expected ${expected}, got ${actual}")
  endif()
endfunction()

info_json("${ASSETS}/characters/CesiumMan/glTF-Binary/CesiumMan.glb" j)
string(JSON vertices GET "${j}" meshes 0 vertices)
string(JSON bones LENGTH "${j}" bones)
string(JSON root_parent GET "${j}" bones 0 parent)
string(JSON influences GET "${j}" max_influences)
string(JSON clips LENGTH "${j}" clips)
string(JSON duration GET "${j}" clips 0 duration)
expect("${vertices}" 3273 "CesiumMan vertices")
expect("${bones}" 19 "CesiumMan bones")
expect("${root_parent}" -1 "CesiumMan root parent")
expect("${influences}" 4 "CesiumMan max influences")
expect("${clips}" 1 "CesiumMan clips")
if(duration LESS 1.95 OR duration GREATER 1.96)
  message(FATAL_ERROR "CesiumMan clip duration ${duration}, expected 2 - 0.0417")
endif()

info_json("${ASSETS}/characters/assimp_collada_library_animation_clips/library_animation_clips.dae" j)
string(JSON clip0 GET "${j}" clips 0 name)
string(JSON clip1 GET "${j}" clips 1 name)
string(JSON bones LENGTH "${j}" bones)
expect("${clip0}/${clip1}" "bend/turn" "Collada clip names")
expect("${bones}" 5 "Collada bones")

info_json("${ASSETS}/motion/makehuman_walk1.bvh" j)
string(JSON bones LENGTH "${j}" bones)
string(JSON meshes LENGTH "${j}" meshes)
expect("${bones}" 75 "walk1 joints")
expect("${meshes}" 0 "walk1 meshes")

# Garbage and missing files: exit 1, message names the file.
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/garbage.glb" "this is not a GLB at all")
foreach(bad "${WORK}/garbage.glb" "${WORK}/missing.fbx")
  execute_process(COMMAND "${CLI}" info "${bad}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect("${rc}" 1 "exit code for ${bad}")
  string(FIND "${err}" "${bad}" at)
  if(at LESS 0)
    message(FATAL_ERROR "error message does not name ${bad}: ${err}")
  endif()
endforeach()

# pose with a BVH motion on its own skeleton, to PLY.
execute_process(COMMAND "${CLI}" pose "${ASSETS}/characters/RiggedSimple/RiggedSimple.gltf" --time 1 --out "${WORK}/rs.ply"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
expect("${rc}" 0 "pose to PLY: ${err}")
file(READ "${WORK}/rs.ply" header LIMIT 32)
string(FIND "${header}" "binary_little_endian" at)
if(at LESS 0)
  message(FATAL_ERROR "PLY header missing: ${header}")
endif()
execute_process(COMMAND "${CLI}" pose "${ASSETS}/characters/SimpleSkin/SimpleSkin.gltf" --time 1 --clip nosuchclip --out "${WORK}/x.obj"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
expect("${rc}" 1 "unknown clip exit code")

# The built-in mannequin driven by CMU motion capture through the shipped name map.
execute_process(COMMAND "${CLI}" pose default --motion "${ASSETS}/motion/cmu_01_01.bvh"
                        --map "${SOURCE_DIR}/resources/motion_maps/cmu_to_default.txt" --time 3 --out "${WORK}/cmu.obj"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
expect("${rc}" 0 "pose default with CMU motion: ${err}")
file(STRINGS "${WORK}/cmu.obj" vertex_lines REGEX "^v ")
list(LENGTH vertex_lines vertex_count)
if(vertex_count LESS 1000)
  message(FATAL_ERROR "posed mannequin has only ${vertex_count} vertices")
endif()
