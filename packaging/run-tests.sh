#!/usr/bin/env bash
# Sets everything up (Debian packages, Release build) and runs the whole test
# suite with ctest under a virtual X server (render and GUI tests need X).
# The soak runs (hours) are left out: `ctest -L soak` in build/ runs them.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$top/packaging/install-deps.sh"
"$top/packaging/build.sh"
"$top/packaging/install-test-tools.sh"
build="${MANNEQUIN_BUILD_DIR:-$top/build}"
cd "$build"
export LIBGL_ALWAYS_SOFTWARE=1
exec xvfb-run -a -s "-screen 0 1600x1000x24" ctest --output-on-failure -LE soak -j "${MANNEQUIN_TEST_JOBS:-2}"
