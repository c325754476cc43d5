#!/usr/bin/env bash
# ./test.sh: installs what is missing, builds (warnings as errors), runs every test through ctest.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
scripts/build.sh ci
ctest --preset ci -j "$(nproc)" "$@"
