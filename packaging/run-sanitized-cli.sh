#!/usr/bin/env bash
# Runs mannequin-cli's end-to-end tests (the commands the README shows, on
# the shared assets and the example scenes; ctest label app) with the CLI
# built under AddressSanitizer, UndefinedBehaviorSanitizer and
# LeakSanitizer, in the same build-asan/ as packaging/run-sanitizers.sh
# (no render command: Debian's VTK is not built for ASan).
#   ./packaging/run-sanitized-cli.sh [ctest arguments]
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MANNEQUIN_ASAN_BUILD_DIR:-$top/build-asan}"
"$top/packaging/install-deps.sh"
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g"
cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMANNEQUIN_WITH_GUI=OFF \
  -DMANNEQUIN_WITH_BENCH=OFF "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j "${MANNEQUIN_JOBS:-$(nproc)}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export LSAN_OPTIONS="suppressions=$top/packaging/lsan.supp"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
ctest -L app --output-on-failure -j "${MANNEQUIN_TEST_JOBS:-2}" --timeout 1800 "$@"
