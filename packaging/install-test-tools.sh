#!/usr/bin/env bash
# Installs the test-only tools: from npm the Khronos glTF-Validator, into the
# build folder at the versions tests/interop/package-lock.json pins (needs
# Node.js and npm: installs Debian's when missing); from Debian ezdxf, the DXF
# reader and writer the pattern tests check Mannequin's DXF against.
# Idempotent.
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tools="${MANNEQUIN_BUILD_DIR:-$top/build}/test-tools"

debian=()
command -v node >/dev/null && command -v npm >/dev/null || debian+=(nodejs npm)
dpkg-query -W -f='${Status}' python3-ezdxf 2>/dev/null | grep -q "install ok installed" || debian+=(python3-ezdxf)
if [ ${#debian[@]} -gt 0 ]; then
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${debian[@]}"
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
