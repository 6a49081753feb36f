# Long runs stay finite, within the stretch limit (cloth: 1.10; hair
# segments: 10 %), and flat in memory.
#   cmake -DCLI=mannequin-cli -DSCENES=resources/scenes -DWORK=DIR [-DSTEPS=N]
#         [-DHAIR_FRAMES=N] [-DOUTFIT_FRAMES=N] [-DFABRICS=a;b] [-DINTEGRATORS=a;b]
#         [-DSTYLES=a;b] -P soak.cmake
# Every fabric preset under every integrator on the sheet with colliders for
# STEPS solver steps, every built-in hairstyle's dynamics on the walk, and
# the garment outfit. An explicit integrator takes about 100,000 steps a
# frame on the sheet: it runs one frame at the frame rate that makes it
# STEPS steps (measured by a short probe); the implicit one runs as many
# frames at the scene's rate as make STEPS steps.
# ctest -L soak runs it with the issue's lengths (hours on 2 cores);
# soak_script (label app) runs it with tiny ones, so the script itself is tested.
if(NOT DEFINED STEPS)
  set(STEPS 10000)
endif()
if(NOT DEFINED HAIR_FRAMES)
  set(HAIR_FRAMES 10000)
endif()
if(NOT DEFINED OUTFIT_FRAMES)
  set(OUTFIT_FRAMES 3000)
endif()
if(NOT DEFINED FABRICS)
  set(FABRICS cotton silk denim wool leather)
endif()
if(NOT DEFINED INTEGRATORS)
  set(INTEGRATORS symplectic_euler verlet rk4 implicit_euler)
endif()
if(NOT DEFINED STYLES)
  set(STYLES long_straight bob wavy curly)
endif()
file(MAKE_DIRECTORY "${WORK}")
set(failures "")

# In soak(): the stat KEY of `json`, when present, goes in the report as
# LABEL and in the problems when above LIMIT.
macro(at_most key label limit)
  string(JSON value ERROR_VARIABLE none GET "${json}" ${key})
  if(NOT value MATCHES "NOTFOUND" AND NOT value STREQUAL "")
    string(APPEND report " ${label} ${value};")
    if(value GREATER ${limit})
      string(APPEND problems " ${label} ${value} above ${limit};")
    endif()
  endif()
endmacro()

# Runs one scene; checks the stats it wrote.
# ARGN: more simulate options (--fps F).
function(soak name scene frames)
  set(stats "${WORK}/${name}.stats.json")  # beside the scene, not over it
  execute_process(COMMAND "${CLI}" simulate "${scene}" --frames ${frames} ${ARGN} --stats-json "${stats}"
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    set(failures "${failures}\n${name}: exit ${code}: ${err}" PARENT_SCOPE)
    return()
  endif()
  file(READ "${stats}" json)
  set(problems "")
  set(report "${name}:")
  foreach(prefix "" "hair_")
    foreach(corner bbox_min bbox_max)
      string(JSON type ERROR_VARIABLE none TYPE "${json}" ${prefix}${corner})
      if(type STREQUAL "ARRAY")
        foreach(i 0 1 2)
          string(JSON t TYPE "${json}" ${prefix}${corner} ${i})
          if(NOT t STREQUAL "NUMBER")
            string(APPEND problems " ${prefix}${corner} is not finite;")
          endif()
        endforeach()
      endif()
    endforeach()
    string(JSON start ERROR_VARIABLE none GET "${json}" ${prefix}rss_mb_after_first_frame)
    string(JSON end ERROR_VARIABLE none GET "${json}" ${prefix}rss_mb_end)
    if(NOT start MATCHES "NOTFOUND" AND NOT end MATCHES "NOTFOUND" AND NOT start STREQUAL "" AND NOT end STREQUAL "")
      string(APPEND report " ${prefix}memory ${start} -> ${end} MB;")
      string(REGEX REPLACE "[.].*$" "" limit "${start}")  # math() takes integers only
      math(EXPR limit "${limit} + ${limit} / 10 + 20")
      # Under AddressSanitizer freed memory waits in its quarantine, so the
      # resident size grows without a leak (LeakSanitizer checks leaks there).
      if(end GREATER limit AND NOT DEFINED ENV{ASAN_OPTIONS})
        string(APPEND problems " ${prefix}memory grew from ${start} to ${end} MB;")
      endif()
    endif()
  endforeach()
  # Cloth: 110 % of the rest length; hair: a guide segment 10 % off its length.
  at_most(max_stretch "max stretch" 1.1005)
  at_most(hair_max_length_error "hair max length error" 0.1005)
  message(STATUS "${report}")
  if(NOT problems STREQUAL "")
    set(failures "${failures}\n${name}:${problems}" PARENT_SCOPE)
  endif()
endfunction()

file(READ "${SCENES}/cloth_sheet_colliders.json" sheet)
string(JSON scene_fps GET "${sheet}" cloth fps)
string(REGEX REPLACE "[.].*$" "" scene_fps "${scene_fps}")
set(probe_fps 1000)
foreach(fabric ${FABRICS})
  foreach(integrator ${INTEGRATORS})
    string(JSON scene SET "${sheet}" cloth fabric "\"${fabric}\"")
    string(JSON scene SET "${scene}" cloth integrator "\"${integrator}\"")
    set(name sheet_${fabric}_${integrator})
    set(path "${WORK}/${name}.json")
    file(WRITE "${path}" "${scene}")
    if(integrator STREQUAL "implicit_euler")
      set(fps ${scene_fps})
    else()
      set(fps ${probe_fps})
    endif()
    execute_process(COMMAND "${CLI}" simulate "${path}" --frames 1 --fps ${fps} --stats-json "${WORK}/probe.json"
                    RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
      string(APPEND failures "\n${name}: the probe failed: ${err}")
      continue()
    endif()
    file(READ "${WORK}/probe.json" probe)
    string(JSON substeps GET "${probe}" substeps_per_frame)
    string(REGEX REPLACE "[.].*$" "" substeps "${substeps}")
    if(integrator STREQUAL "implicit_euler")
      math(EXPR frames "(${STEPS} + ${substeps} - 1) / ${substeps}")
      soak(${name} "${path}" ${frames})
    else()
      # substeps * probe_fps steps a second: one frame of STEPS steps.
      math(EXPR fps "(${substeps} * ${probe_fps}) / ${STEPS}")
      if(fps LESS ${scene_fps})
        set(fps ${scene_fps})
      endif()
      soak(${name} "${path}" 1 --fps ${fps})
    endif()
  endforeach()
endforeach()
foreach(style ${STYLES})
  # On the default mannequin's walk.
  file(READ "${SCENES}/hair_${style}.json" hair)
  string(JSON hair SET "${hair}" animation clip "\"walk\"")
  file(WRITE "${WORK}/hair_${style}.json" "${hair}")
  soak(hair_${style} "${WORK}/hair_${style}.json" ${HAIR_FRAMES})
endforeach()
soak(garment_outfit "${SCENES}/garment_outfit_walk.json" ${OUTFIT_FRAMES})

if(NOT failures STREQUAL "")
  message(FATAL_ERROR "soak failures:${failures}")
endif()
