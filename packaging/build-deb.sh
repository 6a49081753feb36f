#!/usr/bin/env bash
# Builds Mannequin in Release (packaging/build.sh, into build/ or
# $MANNEQUIN_BUILD_DIR) and packs it as a Debian package with CPack
# (packaging/CMakeLists.txt). Prints the .deb's path; install it with
#   sudo apt install ./build/mannequin_*.deb
# Extra arguments go to CMake, as with build.sh.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MANNEQUIN_BUILD_DIR:-$top/build}"
"$top/packaging/install-deps.sh" >&2
"$top/packaging/build.sh" "$@" >&2
rm -f "$build"/mannequin_*.deb
(cd "$build" && cpack -G DEB -B "$build") >&2
ls "$build"/mannequin_*.deb
