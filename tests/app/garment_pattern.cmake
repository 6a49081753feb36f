# mannequin-cli garment --export-pattern: the T-shirt of the outfit scene as
# an SVG pattern with a 10 mm seam allowance: a sewing line and a cutting
# line per panel, both edges of every seam marked, and a sheet at 1:1.
#   -DCLI=<exe> -DSCENE=<scene> -DOUT=<file.svg>
file(REMOVE "${OUT}")
execute_process(COMMAND "${CLI}" garment "${SCENE}" --garment T-shirt --export-pattern "${OUT}" --seam-allowance 10
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit ${code}\nstdout: ${out}\nstderr: ${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "garment --export-pattern failed")
endif()
file(READ "${OUT}" svg)
function(expect_count what regex count)
  string(REGEX MATCHALL "${regex}" found "${svg}")
  list(LENGTH found n)
  if(NOT n EQUAL count)
    message(FATAL_ERROR "${n} ${what} in the pattern, expected ${count}")
  endif()
endfunction()
expect_count("sewing lines" "class=\"sew\"" 4)
expect_count("cutting lines" "class=\"cut\"" 4)
expect_count("seam edges" "class=\"seam\"" 20)
expect_count("notches" "class=\"notch\"" 20)
expect_count("grain lines" "class=\"grain\"" 4)
# Millimetres: the sheet is over a metre and a half wide (four panels side by side).
if(NOT svg MATCHES "width=\"([0-9]+)[.][0-9]+mm\"" OR CMAKE_MATCH_1 LESS 1500)
  message(FATAL_ERROR "the sheet is not at true scale in millimetres")
endif()
