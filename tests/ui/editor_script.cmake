# The editor's command line scripts it: add a garment, go to a time, select
# a bone, save, take a screenshot and quit with status 0.
#   cmake -DEDITOR=mannequin -DWORK=DIR -P editor_script.cmake (under X)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${EDITOR}" default --add-garment skirt --clip walk --time 0.3 --select head
                        --save-as "${WORK}/scripted.mqscene" --screenshot "${WORK}/scripted.png" --size 800x600
                RESULT_VARIABLE code ERROR_VARIABLE err TIMEOUT 240)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "exit ${code}: ${err}")
endif()
if(NOT EXISTS "${WORK}/scripted.png")
  message(FATAL_ERROR "no screenshot")
endif()
file(READ "${WORK}/scripted.mqscene" scene)
string(JSON garment GET "${scene}" garments 0 name)
string(JSON clip GET "${scene}" animation clip)
string(JSON time GET "${scene}" animation time)
if(NOT garment STREQUAL "Skirt" OR NOT clip STREQUAL "walk")
  message(FATAL_ERROR "saved garment '${garment}', clip '${clip}'")
endif()
message(STATUS "saved the skirt on clip ${clip} at ${time} s, and the screenshot")
