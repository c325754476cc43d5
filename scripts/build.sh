#!/usr/bin/env bash
# Configures (once) and builds a CMake preset; all build output goes to stderr.
set -euo pipefail
preset=${1:-release}
cd "$(dirname "$0")/.."
if [ ! -f "build/$preset/CMakeCache.txt" ]; then
  cmake --preset "$preset" >&2
fi
cmake --build --preset "$preset" -j "$(nproc)" >&2
