#!/usr/bin/env bash
# ./test.sh [--long] [CTEST ARGS...]: installs what is missing, builds (warnings as errors), runs
# the tests through ctest. The longest whole-simulation checks (ctest label `long`,
# tests/long_tests.cmake) run only with --long, as CI runs them (.ci/run).
set -euo pipefail
cd "$(dirname "$0")"
long=0
args=()
for a in "$@"; do
  if [ "$a" = --long ]; then long=1; else args+=("$a"); fi
done
scripts/install-deps.sh
scripts/build.sh ci
if [ "$long" = 1 ]; then
  ctest --preset ci -j "$(nproc)" "${args[@]}"
else
  ctest --preset ci -j "$(nproc)" -LE long "${args[@]}"
fi
