# mannequin-cli garment with DXF patterns: the outfit's T-shirt written as DXF
# (10 mm seam allowance), read back into a scene without garments as a new
# garment, listed with the same panels and seams, and simulated.
#   -DCLI=<exe> -DSCENE=<outfit scene> -DDIR=<scratch folder>
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
function(run expect_code)
  execute_process(COMMAND "${CLI}" ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("mannequin-cli ${ARGN}: exit ${code}\nstdout: ${out}\nstderr: ${err}")
  if(NOT code EQUAL expect_code)
    message(FATAL_ERROR "exit ${code}, expected ${expect_code}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run(0 garment "${SCENE}" --garment T-shirt --export-pattern "${DIR}/tshirt.dxf" --seam-allowance 10)
file(READ "${DIR}/tshirt.dxf" dxf)
foreach(layer 1 2 4 7 14)  # the AAMA layers: boundary, turn points, notches, grain, sew line
  if(NOT dxf MATCHES "\n *8\r?\n${layer}\r?\n")
    message(FATAL_ERROR "no entity on layer ${layer}")
  endif()
endforeach()

file(WRITE "${DIR}/bare.mqscene" "{\"format\": \"mannequin-scene\", \"version\": 1, \"character\": \"default\"}")
run(0 garment "${DIR}/bare.mqscene" --import-pattern "${DIR}/tshirt.dxf" --save-as "${DIR}/dressed.mqscene")
run(0 garment "${SCENE}" --garment T-shirt --json)
string(REGEX REPLACE "\"scene\": \"[^\"]*\"" "" before "${out}")
run(0 garment "${DIR}/dressed.mqscene" --json)
string(REGEX REPLACE "\"scene\": \"[^\"]*\"" "" after "${out}")
if(NOT before STREQUAL after)
  message(FATAL_ERROR "the imported T-shirt differs from the exported one")
endif()
run(0 simulate "${DIR}/dressed.mqscene" --frames 3)
if(NOT out MATCHES "simulated 3 frames of [0-9]+ cloth vertices.*penetrating vertices 0")
  message(FATAL_ERROR "simulate reported no cloth")
endif()
