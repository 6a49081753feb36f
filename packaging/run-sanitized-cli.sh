#!/usr/bin/env bash
# mannequin-cli's end-to-end tests (ctest label app) under ASan, UBSan and
# LeakSanitizer: see packaging/run-sanitizers.sh.
exec "$(dirname "${BASH_SOURCE[0]}")/run-sanitizers.sh" --app "$@"
