# Packs the build tree as a .deb, unpacks it and runs what it installed.
#   cmake -DCPACK=<cpack> -DDPKG_DEB=<dpkg-deb> [-DDESKTOP_FILE_VALIDATE=<program>]
#         -DBUILD_DIR=<build tree> -DWORK=<scratch folder> -P package_check.cmake
# Needs a display for the render (ctest runs under xvfb-run).

# run(<expected exit code> <output regex> command...): the command's stdout and stderr must match.
function(run expected regex)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status STREQUAL "${expected}" OR NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "`${ARGN}` exited with ${status} (expected ${expected}), output not matching "
                        "'${regex}':\n${out}${err}")
  endif()
  set(output "${out}${err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# --- the package ---------------------------------------------------------------
run(0 "package: .*mannequin_.*\\.deb generated"
    "${CPACK}" -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK}")
file(GLOB deb "${WORK}/mannequin_*.deb")
list(LENGTH deb count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one mannequin_*.deb in ${WORK}, found: ${deb}")
endif()
message(STATUS "package: ${deb}")

# Metadata: the libraries dpkg-shlibdeps found, plus what it cannot see.
run(0 "Package: mannequin\n" "${DPKG_DEB}" --info "${deb}")
foreach(field "Section: graphics" "Maintainer: Mannequin developers" "Recommends: xvfb"
              "Depends: [^\n]*libqt6widgets6" "Depends: [^\n]*libvtk9\\.1" "Depends: [^\n]*libgl1-mesa-dri")
  if(NOT output MATCHES "${field}")
    message(FATAL_ERROR "dpkg-deb --info: no '${field}' in:\n${output}")
  endif()
endforeach()

# --- its contents -----------------------------------------------------------------
set(root "${WORK}/root")
run(0 "" "${DPKG_DEB}" --extract "${deb}" "${root}")
file(GLOB programs RELATIVE "${root}/usr/bin" "${root}/usr/bin/*")
list(SORT programs)
if(NOT programs STREQUAL "mannequin;mannequin-cli")
  message(FATAL_ERROR "usr/bin holds '${programs}', expected the two programs only (no tests or benchmarks)")
endif()
foreach(path
    usr/share/applications/mannequin.desktop
    usr/share/icons/hicolor/scalable/apps/mannequin.svg
    usr/share/mime/packages/mannequin.xml
    usr/share/man/man1/mannequin.1.gz
    usr/share/man/man1/mannequin-cli.1.gz
    usr/share/doc/mannequin/copyright
    usr/share/doc/mannequin/changelog.gz
    usr/share/mannequin/scenes/garment_tshirt_walk.json
    usr/share/mannequin/scenes/hair_bob.json
    usr/share/mannequin/motion_maps/cmu_to_default.txt)
  if(NOT EXISTS "${root}/${path}")
    message(FATAL_ERROR "the package has no ${path}")
  endif()
endforeach()

file(READ "${root}/usr/share/applications/mannequin.desktop" desktop)
if(NOT desktop MATCHES "\nExec=mannequin %f\n" OR NOT desktop MATCHES "\nMimeType=application/x-mannequin-scene;")
  message(FATAL_ERROR "the desktop entry does not open scenes with the editor:\n${desktop}")
endif()
if(DESKTOP_FILE_VALIDATE)
  run(0 "" "${DESKTOP_FILE_VALIDATE}" "${root}/usr/share/applications/mannequin.desktop")
endif()
file(READ "${root}/usr/share/mime/packages/mannequin.xml" mime)
if(NOT mime MATCHES "type=\"application/x-mannequin-scene\"" OR NOT mime MATCHES "pattern=\"\\*\\.mqscene\"")
  message(FATAL_ERROR "the MIME package does not declare *.mqscene:\n${mime}")
endif()
# The CLI's page lists every command's options.
run(0 "\\.TH MANNEQUIN-CLI \"1\".*\\.SH COMMANDS.*\\.SS render" gzip -dc "${root}/usr/share/man/man1/mannequin-cli.1.gz")
run(0 "\\.TH MANNEQUIN \"1\".*screenshot.*\\.SH \"SEE ALSO\"" gzip -dc "${root}/usr/share/man/man1/mannequin.1.gz")

# --- the unpacked programs run ------------------------------------------------------
run(0 "^mannequin-cli [0-9]+\\.[0-9]+\\.[0-9]+\n" "${root}/usr/bin/mannequin-cli" --version)
run(0 "^Mannequin [0-9]+\\.[0-9]+\\.[0-9]+\n" "${root}/usr/bin/mannequin" --version)
run(0 "" "${root}/usr/bin/mannequin-cli" info "${root}/usr/share/mannequin/scenes/garment_tshirt_walk.json")
run(0 "" "${root}/usr/bin/mannequin-cli" render default --out "${WORK}/x.png" --size 160x120)
file(READ "${WORK}/x.png" signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "render wrote no PNG (${WORK}/x.png starts with ${signature})")
endif()
message(STATUS "the package installs and its programs run")
