#!/usr/bin/env bash
# scripts/build.sh PRESET [TARGET...]: configures (once) and builds a CMake preset, all
# targets or only the ones named; all build output goes to stderr.
set -euo pipefail
preset=${1:-release}
shift || true
cd "$(dirname "$0")/.."
if [ ! -f "build/$preset/CMakeCache.txt" ]; then
  cmake --preset "$preset" >&2
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build --preset "$preset" -j "$(nproc)" "${targets[@]}" >&2
