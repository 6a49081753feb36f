# A take's garment frames are simulate's frames: exports the scene with
# --with garments, simulates it with OBJ frames, poses the take at a frame's
# time and compares its last mesh (the garment) with simulate's OBJ.
#   -DCLI=<mannequin-cli> -DDIFF=<mannequin_obj_diff> -DSCENE=<scene> -DGARMENT=<garment0_T-shirt> -DOUT_DIR=<dir>
set(frames 6)
set(frame 5)  # take frame 5 = simulate's sixth frame
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
function(run)
  execute_process(COMMAND "${CLI}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  message("${CLI} ${ARGN}\n${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "exit ${status}")
  endif()
endfunction()
run(export "${SCENE}" --with garments --frames ${frames} --fps 30 --out "${OUT_DIR}/take.glb")
run(simulate "${SCENE}" --frames ${frames} --fps 30 --export-dir "${OUT_DIR}/frames")
math(EXPR simulate_frame "${frame} + 1")
string(LENGTH "000${simulate_frame}" length)
math(EXPR skip "${length} - 4")
string(SUBSTRING "000${simulate_frame}" ${skip} 4 number)
run(pose "${OUT_DIR}/take.glb" --time 0.16666667 --out "${OUT_DIR}/take_frame.obj")
execute_process(COMMAND "${DIFF}" "${OUT_DIR}/take_frame.obj" "${OUT_DIR}/frames/${GARMENT}_${number}.obj" 1e-5 --tail
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the take's garment differs from simulate's frame ${simulate_frame}")
endif()
