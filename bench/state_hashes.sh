#!/usr/bin/env bash
# bench/state_hashes.sh [HEARTSIM]: the state_hash of the redesign's reference runs
# (heart-only, dam-break, paper-chamber-beating, normal for 2 s), on 1 and 2 threads, one line
# each. A change that keeps the physics must print the same lines before and after.
set -euo pipefail
bin=${1:-build/release/apps/heartsim}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for case in "heart-only" "dam-break" "paper-chamber-beating" "normal --duration 2"; do
  for threads in 1 2; do
    # shellcheck disable=SC2086
    hash=$("$bin" run $case --threads "$threads" --json --out "$out/run" 2>/dev/null |
      sed -n 's/.*"state_hash": *"\([0-9a-f]*\)".*/\1/p')
    printf '%-24s threads=%d %s\n' "${case%% *}" "$threads" "$hash"
  done
done
