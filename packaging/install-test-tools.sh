#!/usr/bin/env bash
# Installs the test-only tools that come from npm (the Khronos glTF-Validator)
# into the build folder, at the versions tests/interop/package-lock.json pins.
# Needs Node.js and npm: installs Debian's when missing. Idempotent.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tools="${MANNEQUIN_BUILD_DIR:-$top/build}/test-tools"

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends nodejs npm
fi

mkdir -p "$tools"
if cmp -s "$top/tests/interop/package-lock.json" "$tools/package-lock.json" &&
   [ -d "$tools/node_modules/gltf-validator" ]; then
  echo "install-test-tools: gltf-validator present"
  exit 0
fi
cp "$top/tests/interop/package.json" "$top/tests/interop/package-lock.json" "$tools/"
(cd "$tools" && npm ci --no-audit --no-fund --loglevel=error)
echo "install-test-tools: installed gltf-validator into $tools"
