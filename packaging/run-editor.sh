#!/usr/bin/env bash
# Sets everything up (Debian packages, Release build) and opens the editor on
# its built-in default scene. Extra arguments go to the editor (e.g. a file).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$top/packaging/install-deps.sh"
"$top/packaging/build.sh"
build="${MANNEQUIN_BUILD_DIR:-$top/build}"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "run-editor: no display found; starting the editor inside a virtual X server (xvfb-run)." >&2
  exec xvfb-run -a -s "-screen 0 1600x1000x24" "$build/app/mannequin" "$@"
fi
exec "$build/app/mannequin" "$@"
