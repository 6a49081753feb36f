#!/usr/bin/env bash
# Configures and builds Mannequin in Release into build/ (or $MANNEQUIN_BUILD_DIR).
# MANNEQUIN_WERROR=1 makes any compiler warning fail the build (CI does).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MANNEQUIN_BUILD_DIR:-$top/build}"
jobs="${MANNEQUIN_JOBS:-$(nproc)}"
werror=OFF
[ "${MANNEQUIN_WERROR:-0}" = 1 ] && werror=ON
cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMANNEQUIN_WERROR=$werror "$@" >/dev/null
cmake --build "$build" -j "$jobs"
