#!/usr/bin/env bash
# Fuzzes Mannequin's readers with libFuzzer under AddressSanitizer and
# UndefinedBehaviorSanitizer (Debian's clang-14), one target after another.
#   ./packaging/fuzz.sh [--runs N] [--seconds S] [--jobs J] [--timeout T] [TARGET ...]
# Targets (tests/fuzz/fuzz_<target>.cpp): gltf bvh scene hairstyle garment
# motion_map assimp point_cache dxf; all of them by default. Each runs N executions (default
# 1,000,000; stopped after S seconds if given and sooner), starting from its
# seeds and from what earlier runs kept (build-fuzz/corpus/<target>). A crash, leak, timeout or
# out-of-memory stops the target and leaves the input in
# build-fuzz/findings/<target>/; copy it into tests/fuzz/regressions/<target>/
# once fixed, where ctest replays it in the normal build (an input mutated
# from a ../shared asset goes in as a .patch of it: tests/fuzz/replay_main.cpp).
# --timeout T: seconds one input may take (default 10); libFuzzer counts wall
# time, so a fuzzer sharing a busy machine (run under nice) needs more.
# assimp: Assimp itself aborts or runs out of memory on some damaged files,
# which Mannequin survives by reading each file first in a bounded child
# process. A fork per input is too slow for fuzzing, so this build reads in
# process (core/CMakeLists.txt), libFuzzer runs in -fork mode and keeps going
# past such inputs, and every one it kept is then replayed under ASan through
# the real isolation (packaging/run-sanitizers.sh --replay), which must refuse
# it cleanly.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MANNEQUIN_FUZZ_BUILD_DIR:-$top/build-fuzz}"
runs=1000000
seconds=0
jobs="$(nproc)"
timeout=10
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --timeout) timeout="$2"; shift 2 ;;
    -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(gltf bvh scene hairstyle garment motion_map assimp point_cache dxf)

"$top/packaging/install-deps.sh"
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g"
rm -f "$build/fuzz_seeds.txt"
CC=clang-14 CXX=clang++-14 cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DMANNEQUIN_WITH_GUI=OFF -DMANNEQUIN_WITH_TESTS=OFF -DMANNEQUIN_WITH_BENCH=OFF -DMANNEQUIN_WITH_FUZZERS=ON \
  "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j "$jobs" --target $(printf 'fuzz_%s ' "${targets[@]}")

export ASAN_OPTIONS=detect_leaks=1
export LSAN_OPTIONS="suppressions=$top/packaging/lsan.supp"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target" findings="$build/findings/$target"
  mkdir -p "$corpus" "$findings"
  # libFuzzer takes folders: the seeds are copied into the corpus.
  read -r -a seeds <<<"$(grep "^$target " "$build/fuzz_seeds.txt" | cut -d' ' -f2-)"
  for seed in "${seeds[@]}"; do
    if [ -d "$seed" ]; then cp -n "$seed"/* "$corpus"/; else cp -n "$seed" "$corpus"/; fi
  done
  # Assimp reads a few inputs a second at full length under ASan: shorter
  # inputs (the small seed in tests/fuzz/seeds/assimp) reach its parsers' branches faster.
  max_len=600000
  modes=()
  # DXF: every successful read is written and read back; 8 KB holds a
  # few pieces and keeps that near a thousand inputs a second.
  [ "$target" = dxf ] && max_len=8192
  if [ "$target" = assimp ]; then
    max_len=65536
    modes=(-fork="$jobs" -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
  fi
  dict="$top/tests/fuzz/$target.dict"
  [ -f "$dict" ] || dict="$top/tests/fuzz/json.dict"
  echo "== fuzz_$target"
  if ! "$build/tests/fuzz/fuzz_$target" "$corpus" -runs="$runs" -max_total_time="$seconds" -dict="$dict" -timeout="$timeout" -rss_limit_mb=3072 \
      -max_len="$max_len" -print_final_stats=1 -artifact_prefix="$findings/" "${modes[@]}" 2>"$build/fuzz_$target.log"; then
    status=1
    echo "fuzz_$target: FOUND a problem, see $build/fuzz_$target.log and $findings/"
  fi
  # The last line of -fork mode's progress has its total count.
  grep -E "^stat::number_of_executed_units|^Done" "$build/fuzz_$target.log" ||
    grep -E "^#[0-9]+: " "$build/fuzz_$target.log" | tail -1 || tail -5 "$build/fuzz_$target.log"
  if [ ${#modes[@]} -gt 0 ] && [ -n "$(ls -A "$findings")" ]; then
    echo "fuzz_$target: replaying $(ls "$findings" | wc -l) kept inputs through the isolated reader under ASan"
    "$top/packaging/run-sanitizers.sh" --replay "$target" "$findings" || status=1
  fi
done
exit $status
