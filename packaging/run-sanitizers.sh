#!/usr/bin/env bash
# Builds core, sim and their tests with AddressSanitizer,
# UndefinedBehaviorSanitizer and LeakSanitizer into build-asan/ and runs
# them. Any report fails.
#   ./packaging/run-sanitizers.sh [--app|--gui] [ctest arguments, e.g. -R Skin]
#   ./packaging/run-sanitizers.sh --replay TARGET FILE|DIR ...
# Without --app: the unit tests (and the fuzz targets' replays). With --app:
# mannequin-cli's end-to-end tests
# (label app: the README's commands on the shared assets and example scenes;
# no render command). --gui: the editor too (render, ui, app), and the
# editor's tests (label gui) under Xvfb, e.g. `--gui -R gui_monkey`; our
# code is checked, Debian's Qt, VTK and Mesa are not instrumented (and
# leaks are not checked: see below). --replay: runs fuzz target TARGET's entry point
# (tests/fuzz/fuzz_TARGET.cpp) over inputs a fuzzer kept.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MANNEQUIN_ASAN_BUILD_DIR:-$top/build-asan}"
label=unit
replay=""
gui=OFF
if [ "${1:-}" = --app ]; then
  label=app
  shift
elif [ "${1:-}" = --gui ]; then
  label=gui
  gui=ON
  shift
elif [ "${1:-}" = --replay ]; then
  replay="$2"
  shift 2
fi
"$top/packaging/install-deps.sh"
# The end-to-end tests check exported glTF with the Khronos validator.
[ "$label" = unit ] || MANNEQUIN_BUILD_DIR="$build" "$top/packaging/install-test-tools.sh"
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g"
cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMANNEQUIN_WITH_GUI=$gui \
  -DMANNEQUIN_WITH_BENCH=OFF "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j "${MANNEQUIN_JOBS:-$(nproc)}" ${replay:+--target "fuzz_replay_$replay"}
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export LSAN_OPTIONS="suppressions=$top/packaging/lsan.supp"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if [ -n "$replay" ]; then
  exec "$build/tests/fuzz/fuzz_replay_$replay" "$@"
fi
cd "$build"
if [ "$gui" = ON ]; then
  # No leak check here: at exit D-Bus and Mesa's driver (loaded at run time,
  # and unloaded before LeakSanitizer reports, so their stacks cannot be
  # named) leave allocations behind; the unit and app runs check leaks.
  export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
  export LIBGL_ALWAYS_SOFTWARE=1
  exec xvfb-run -a -s "-screen 0 1600x1000x24" ctest -L "$label" --output-on-failure -j 1 "$@"
fi
ctest -L "$label" --output-on-failure -j "${MANNEQUIN_TEST_JOBS:-2}" --timeout 1800 "$@"
