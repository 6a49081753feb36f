#!/usr/bin/env bash
# Side-by-side cloth timing against Blender 3.4 (the peer in ../shared/peers/blender):
# for each bench scene, one Blender run and one Mannequin run back to back, so
# both see the same machine. Prints ms per frame, the ratio and the other
# processes' CPU use during each run (a run is only fair on an idle machine).
#
#   tests/bench/compare_blender.sh [BUILD_DIR] [SCENES...]
#   SCENES default: drape_64 pinned_64 drape_128 pinned_128
# Needs the Debian packages blender, python3-numpy (see the peer's README).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$top/build}"
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(drape_64 pinned_64 drape_128 pinned_128)
peers="${MANNEQUIN_SHARED_DIR:-$top/../shared}/peers/blender"
cli="$build/app/mannequin-cli"
frames=120
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT

busy() { awk '/^cpu /{print ($2+$3+$4+$7+$8)/100.0}' /proc/stat; }
# other_cpu SECONDS_BUSY_BEFORE SECONDS_BUSY_AFTER OWN_CPU: CPU others used meanwhile.
other_cpu() { awk -v a="$1" -v b="$2" -v own="$3" 'BEGIN{o=b-a-own; if(o<0)o=0; printf "%.1f", o}'; }
# cpu_of TIMEFILE: user + sys seconds from GNU time's "%U %S".
cpu_of() { awk '{printf "%.2f", $1+$2}' "$1"; }

printf "%-11s %12s %12s %7s %10s %10s %12s %12s\n" scene blender_ms mannequin_ms ratio bl_stretch mq_stretch bl_other_cpu mq_other_cpu
for scene in "${scenes[@]}"; do
  kind="${scene%_*}"
  n="${scene##*_}"
  script="cloth_${kind}.py"

  b0=$(busy)
  (cd "$peers" && env time -f "%U %S" -o "$scratch/bl.time" \
     blender -b --factory-startup --python "$script" -- "$n" "$frames" > "$scratch/bl.out" 2>&1)
  b1=$(busy)
  bl_line=$(grep '^RESULT' "$scratch/bl.out")
  bl_ms=$(sed -n 's/.* per_frame_ms=\([0-9.]*\).*/\1/p' <<<"$bl_line")
  bl_stretch=$(sed -n 's/.* max_stretch=\([0-9.]*\).*/\1/p' <<<"$bl_line")
  bl_other=$(other_cpu "$b0" "$b1" "$(cpu_of "$scratch/bl.time")")

  b0=$(busy)
  env time -f "%U %S" -o "$scratch/mq.time" \
    "$cli" simulate "$top/tests/bench/scenes/$scene.json" --frames "$frames" --stats-json "$scratch/mq.json" \
    > "$scratch/mq.out" 2>&1
  b1=$(busy)
  mq_ms=$(python3 -c "import json,sys; print('%.1f' % json.load(open(sys.argv[1]))['ms_per_frame'])" "$scratch/mq.json")
  mq_stretch=$(python3 -c "import json,sys; print('%.4f' % json.load(open(sys.argv[1]))['max_stretch'])" "$scratch/mq.json")
  mq_other=$(other_cpu "$b0" "$b1" "$(cpu_of "$scratch/mq.time")")

  ratio=$(awk -v b="$bl_ms" -v m="$mq_ms" 'BEGIN{printf "%.1f", b/m}')
  printf "%-11s %12s %12s %7s %10s %10s %12s %12s\n" "$scene" "$bl_ms" "$mq_ms" "${ratio}x" "${bl_stretch:--}" \
    "$mq_stretch" "$bl_other" "$mq_other"
done
