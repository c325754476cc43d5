#!/usr/bin/env bash
# bench/state_hashes.sh [HEARTSIM] [all]: the state_hash of the redesign's reference runs
# (heart-only, dam-break, paper-chamber-beating, normal for 2 s), on 1 and 2 threads, one line
# each; with `all`, every built-in scenario (scenarios/*.toml) at 0.5 s instead. A change that
# keeps the physics must print the same lines before and after.
set -euo pipefail
bin=$(realpath "${1:-build/release/apps/heartsim}")
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
if [ "${2:-}" = all ]; then
  cases=()
  for file in scenarios/*.toml; do
    name=$(basename "$file" .toml)
    cases+=("$name --duration 0.5")
  done
else
  cases=("heart-only" "dam-break" "paper-chamber-beating" "normal --duration 2")
fi
for case in "${cases[@]}"; do
  for threads in 1 2; do
    # shellcheck disable=SC2086
    hash=$("$bin" run $case --threads "$threads" --json --out "$out/run" 2>/dev/null |
      sed -n 's/.*"state_hash": *"\([0-9a-f]*\)".*/\1/p' || true)
    printf '%-28s threads=%d %s\n' "${case%% *}" "$threads" "$hash"
  done
done
