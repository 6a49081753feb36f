#!/usr/bin/env bash
# Configures and builds Mannequin in Release into build/ (or $MANNEQUIN_BUILD_DIR).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MANNEQUIN_BUILD_DIR:-$top/build}"
jobs="${MANNEQUIN_JOBS:-$(nproc)}"
cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j "$jobs"
