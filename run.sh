#!/usr/bin/env bash
# ./run.sh [ARGS...]: installs what is missing, builds, and runs `heartsim ARGS...`.
# Without arguments it opens the viewer where a display exists, else runs the default scenario
# headless and writes its results to results/.
# Build output goes to stderr, so `./run.sh run heart-only --json` prints only JSON on stdout.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
scripts/build.sh release heartsim
if [ $# -eq 0 ]; then
  if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
    set -- view normal
  else
    set -- run normal --out results/normal
  fi
fi
exec build/release/apps/heartsim "$@"
