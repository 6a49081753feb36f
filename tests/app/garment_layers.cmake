# mannequin-cli simulate on trousers + T-shirt (the shirt on layer 1, over the
# trousers): the shirt's hem stays outside the trousers' waistband in every
# frame; with --layers off (UNLAYERED_FRAMES frames) it is inside, so the count does see it.
#   -DCLI=<exe> -DSCENE=<scene.json> -DWORK=<dir> -DFRAMES=<n> -DMAX_INSIDE=<n> -DUNLAYERED_FRAMES=<n>
#   -DMIN_INSIDE_UNLAYERED=<n> -DMAX_PENETRATING=<n>
include("${CMAKE_CURRENT_LIST_DIR}/garment_checks.cmake")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
function(simulate name frames layers)
  simulate_scene("${WORK}/${name}.json" 600 --frames ${frames} --layers ${layers})
  set(stats "${stats}" PARENT_SCOPE)
endfunction()

simulate(layered ${FRAMES} on)
string(JSON inner GET "${stats}" garments 0 name)
string(JSON outer GET "${stats}" garments 1 name)
string(JSON outer_layer GET "${stats}" garments 1 layer)
string(JSON inside GET "${stats}" garments 1 max_inside_inner_vertices)
string(JSON inner_welded GET "${stats}" garments 0 welded)
string(JSON outer_welded GET "${stats}" garments 1 welded)
string(JSON waistband_top GET "${stats}" garments 0 bbox_max 1)
string(JSON hem GET "${stats}" garments 1 bbox_min 1)
string(JSON ms GET "${stats}" ms_per_frame)
string(JSON cpu_ms GET "${stats}" cpu_ms_per_frame)
message("layered: ${outer} (layer ${outer_layer}) over ${inner}: at most ${inside} vertices inside in any frame; "
        "${ms} ms/frame (CPU ${cpu_ms} ms)")
if(NOT inner STREQUAL "trousers" OR NOT outer STREQUAL "T-shirt" OR NOT outer_layer EQUAL 1)
  message(FATAL_ERROR "unexpected garments: ${inner}, ${outer} (layer ${outer_layer})")
endif()
if(NOT inner_welded OR NOT outer_welded)
  message(FATAL_ERROR "the garments' seams were not welded")
endif()
# The shirt covers the waistband (so the count means something).
if(NOT hem LESS waistband_top)
  message(FATAL_ERROR "the shirt's hem (y ${hem}) does not reach below the trousers' top (y ${waistband_top})")
endif()
if(inside GREATER ${MAX_INSIDE})
  message(FATAL_ERROR "${inside} shirt vertices inside the trousers in a frame (at most ${MAX_INSIDE})")
endif()
check_body_and_stretch("${stats}" max_penetrating_vertices ${MAX_PENETRATING} " in a frame")

simulate(unlayered ${UNLAYERED_FRAMES} off)
string(JSON unlayered_inside GET "${stats}" garments 1 max_inside_inner_vertices)
string(JSON unlayered GET "${stats}" layers)
message("unlayered: at most ${unlayered_inside} shirt vertices inside the trousers")
if(unlayered OR unlayered_inside LESS ${MIN_INSIDE_UNLAYERED})
  message(FATAL_ERROR "without layers ${unlayered_inside} shirt vertices inside (expected at least ${MIN_INSIDE_UNLAYERED})")
endif()
