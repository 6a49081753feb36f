# DXF patterns between Mannequin and another program (ezdxf): the outfit's
# T-shirt exported and checked by ezdxf's reader, and a pattern ezdxf writes
# the way pattern CAD programs do, imported into a scene with its pieces' areas.
#   -DCLI=<exe> -DPYTHON=<python3 with ezdxf> -DSCRIPT=<dxf_ezdxf.py> -DSCENE=<outfit scene> -DDIR=<scratch>
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${ARGN}: exit ${code}\nstdout: ${out}\nstderr: ${err}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "failed (exit ${code})")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run("${CLI}" garment "${SCENE}" --garment T-shirt --export-pattern "${DIR}/tshirt.dxf" --seam-allowance 15)
run("${CLI}" garment "${SCENE}" --garment T-shirt --json)
file(WRITE "${DIR}/tshirt.json" "${out}")
run("${PYTHON}" "${SCRIPT}" check "${DIR}/tshirt.dxf" "${DIR}/tshirt.json")

run("${PYTHON}" "${SCRIPT}" write-foreign "${DIR}/foreign.dxf")
set(expected "${out}")
file(WRITE "${DIR}/bare.mqscene" "{\"format\": \"mannequin-scene\", \"version\": 1, \"character\": \"default\"}")
run("${CLI}" garment "${DIR}/bare.mqscene" --import-pattern "${DIR}/foreign.dxf" --save-as "${DIR}/foreign.mqscene")
run("${CLI}" garment "${DIR}/foreign.mqscene" --json)
foreach(piece body pocket)
  string(JSON want GET "${expected}" ${piece})
  string(REGEX MATCH "\"area_cm2\": ([0-9.]+)[^}]*\"name\": \"${piece}\"" found "${out}")
  if(NOT found)
    message(FATAL_ERROR "no imported panel ${piece}")
  endif()
  # CMake's math is integer: whole cm2, compared in tenths of a percent.
  string(REGEX REPLACE "\\..*" "" got_int "${CMAKE_MATCH_1}")
  string(REGEX REPLACE "\\..*" "" want_int "${want}")
  math(EXPR difference "(${got_int} - ${want_int}) * 1000 / ${want_int}")
  if(difference GREATER 5 OR difference LESS -5)
    message(FATAL_ERROR "${piece}: imported ${CMAKE_MATCH_1} cm2, drawn ${want} cm2")
  endif()
endforeach()
