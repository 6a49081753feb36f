#!/usr/bin/env bash
# Installs the Debian 12 packages Mannequin needs to build, test and run.
# Idempotent: when everything is present it only checks and returns.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev libqt6opengl6-dev libxkbcommon-dev
  libvtk9-dev
  libopenmesh-dev libcgal-dev libglm-dev libceres-dev libeigen3-dev libnanoflann-dev
  libassimp-dev nlohmann-json3-dev libstb-dev libtinygltf-dev libdxflib-dev
  libgtest-dev libgmock-dev libbenchmark-dev clang-format-14
  xvfb xauth xdotool libgl1-mesa-dri libglx-mesa0
  help2man dpkg-dev desktop-file-utils
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
