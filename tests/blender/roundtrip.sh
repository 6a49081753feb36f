#!/usr/bin/env bash
# Blender 3.4 reads Mannequin's glTF exports as Mannequin poses them: the
# default mannequin and CesiumMan rigged, and a take of the T-shirt scene and
# of the wavy hair scene (garments and hair baked as morph targets), each
# compared at several times with mannequin-cli's own posed meshes and
# simulation frames (tests/blender/gltf_in_blender.py); then a garment's
# point cache (tests/blender/pc2_in_blender.py). Not in ctest
# (Blender is not a build dependency); run from the repository:
#
#   sudo apt-get install blender python3-numpy
#   tests/blender/roundtrip.sh [BUILD_DIR] [SHARED_DIR]
#
# Prints one line per check and exits 1 when any is past 1e-4 of its bounding-box diagonal.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cli="${1:-$top/build}/app/mannequin-cli"
shared="${2:-$top/../shared}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
check="$top/tests/blender/gltf_in_blender.py"
status=0
blender_check() {
  blender -b --python-exit-code 1 --python "$check" -- "$@" > "$work/blender.log" 2>&1 || status=1
  grep -E "^[A-Za-z_-]+ +t=|^worst|Error|error" "$work/blender.log" || true
}

echo "== default mannequin, rigged, walk"
"$cli" export default --rigged --out "$work/default.glb" >/dev/null
args=()
for t in 0.2 0.5 0.9; do
  "$cli" pose default --clip walk --time "$t" --out "$work/walk_$t.obj" >/dev/null
  args+=(--check mannequin "$t" "$work/walk_$t.obj")
done
blender_check "$work/default.glb" --fps 30 "${args[@]}"

echo "== CesiumMan, rigged"
cesium="$shared/assets/characters/CesiumMan/glTF-Binary/CesiumMan.glb"
"$cli" export "$cesium" --rigged --out "$work/cesium.glb" >/dev/null
# The export samples the clip at 30 fps from its first key (1/24 s): compare
# at samples, where the file's linear keys hold the clip's own values.
start=$("$cli" info "$cesium" --json | python3 -c "import json, sys; print(json.load(sys.stdin)['clips'][0]['start'])")
args=()
for k in 14 29 44; do
  t=$(python3 -c "print($start + $k / 30)")
  "$cli" pose "$cesium" --time "$t" --out "$work/cesium_$t.obj" >/dev/null
  args+=(--check Cesium_Man "$t" "$work/cesium_$t.obj")
done
blender_check "$work/cesium.glb" --fps 30 "${args[@]}"

# A take's frame f is the simulation after f + 1 steps: simulate's frame f + 1.
echo "== T-shirt take: the walk with the simulated T-shirt"
scene="$top/resources/scenes/garment_tshirt_walk.json"
"$cli" export "$scene" --with garments --frames 30 --fps 30 --out "$work/tshirt.glb" >/dev/null
"$cli" simulate "$scene" --frames 30 --fps 30 --export-dir "$work/tshirt_frames" >/dev/null
start=$(python3 -c "import json; print(json.load(open('$scene')).get('time', 0.0))")
args=()
for f in 0 14 29; do
  t=$(python3 -c "print($f / 30)")
  body_time=$(python3 -c "print($start + ($f + 1) / 30)")
  "$cli" pose "$scene" --time "$body_time" --out "$work/body_$f.obj" >/dev/null
  args+=(--check mannequin "$t" "$work/body_$f.obj")
  args+=(--check T-shirt "$t" "$work/tshirt_frames/$(printf 'garment0_T-shirt_%04d.obj' $((f + 1)))")
done
blender_check "$work/tshirt.glb" --fps 30 "${args[@]}"

echo "== hair take: the wavy style's guides on the walk"
scene="$top/resources/scenes/hair_wavy.json"
"$cli" export "$scene" --with hair --frames 20 --fps 30 --out "$work/hair.glb" >/dev/null
"$cli" simulate "$scene" --frames 20 --fps 30 --export-dir "$work/hair_frames" >/dev/null
args=()
for f in 0 9 19; do
  t=$(python3 -c "print($f / 30)")
  args+=(--check-subset hair "$t" "$work/hair_frames/$(printf 'hair_%04d.ply' $((f + 1)))")
done
blender_check "$work/hair.glb" --fps 30 "${args[@]}"

echo "== T-shirt point cache (PC2) through Blender's Mesh Cache modifier"
"$cli" simulate "$top/resources/scenes/garment_tshirt_walk.json" --frames 30 --fps 30 \
  --export-dir "$work/pc2" --export-format pc2 >/dev/null
blender -b --python-exit-code 1 --python "$top/tests/blender/pc2_in_blender.py" -- "$work/pc2/garment0_T-shirt" \
  > "$work/blender.log" 2>&1 || status=1
grep -iE "difference|error" "$work/blender.log" || true

echo "== the wavy hair's guides as an MDD point cache (export --point-cache)"
"$cli" export "$top/resources/scenes/hair_wavy.json" --with hair --frames 10 --fps 30 \
  --point-cache "$work/mdd/take.mdd" >/dev/null
blender -b --python-exit-code 1 --python "$top/tests/blender/pc2_in_blender.py" -- "$work/mdd/take_hair" mdd \
  > "$work/blender.log" 2>&1 || status=1
grep -iE "difference|error" "$work/blender.log" || true
exit $status
