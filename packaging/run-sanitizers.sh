#!/usr/bin/env bash
# Builds core, sim and their tests with AddressSanitizer,
# UndefinedBehaviorSanitizer and LeakSanitizer (no GUI: Debian's Qt and VTK
# are not built for ASan) into build-asan/ and runs them. Any report fails.
#   ./packaging/run-sanitizers.sh [--app] [ctest arguments, e.g. -R Skin]
# Without --app: the unit tests (and the fuzz targets' replays). With --app:
# mannequin-cli's end-to-end tests
# (label app: the README's commands on the shared assets and example scenes;
# no render command).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MANNEQUIN_ASAN_BUILD_DIR:-$top/build-asan}"
label=unit
if [ "${1:-}" = --app ]; then
  label=app
  shift
fi
"$top/packaging/install-deps.sh"
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g"
cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMANNEQUIN_WITH_GUI=OFF \
  -DMANNEQUIN_WITH_BENCH=OFF "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j "${MANNEQUIN_JOBS:-$(nproc)}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export LSAN_OPTIONS="suppressions=$top/packaging/lsan.supp"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
ctest -L "$label" --output-on-failure -j "${MANNEQUIN_TEST_JOBS:-2}" --timeout 1800 "$@"
