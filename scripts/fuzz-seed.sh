#!/usr/bin/env bash
# scripts/fuzz-seed.sh TARGET DIR: puts a fuzz target's seed inputs into DIR (made if missing):
# the built-in scenarios or lessons, the meshes of fuzz/seeds/TARGET/, a checkpoint of `normal`
# written by $HEARTSIM (the release build's heartsim, built if needed, when it is not set), and
# every input kept in fuzz/regressions/TARGET/ (what a fuzzer once found). Files already in DIR
# are kept. Used by scripts/fuzz.sh (the corpus to grow) and scripts/ci-sanitized.sh (replayed).
set -euo pipefail
t=$1 corpus=$2
cd "$(dirname "$0")/.."
mkdir -p "$corpus"
case $t in
  fuzz_scenario) cp -n scenarios/*.toml "$corpus"/ ;;
  fuzz_lesson) cp -n lessons/*.toml "$corpus"/ ;;
  fuzz_mesh_*) cp -n fuzz/seeds/"$t"/* "$corpus"/ ;;  # a marked 6-tet box in each format (tests/io/mesh_writers.h)
  fuzz_patient_wall) cp -n fuzz/seeds/"$t"/* "$corpus"/ ;;  # biv-me's endocardium (first byte: obj, coarse)
  fuzz_checkpoint)  # the last checkpoint of a 4 ms run of `normal`
    if [ ! -f "$corpus/normal-run.hsck" ]; then
      heartsim=${HEARTSIM:-build/release/apps/heartsim}
      [ -n "${HEARTSIM:-}" ] || scripts/build.sh release heartsim
      seed=$(mktemp -d)
      "$heartsim" run normal --duration 0.004 --checkpoint-every 0.002 --out "$seed" >/dev/null
      checkpoints=("$seed"/*.hsck)  # checkpoint_<time>s.hsck, the time zero-padded: the last is the latest
      cp "${checkpoints[-1]}" "$corpus/normal-run.hsck"
      rm -rf "$seed"
    fi ;;
  fuzz_set) for s in "cycle.heart_rate_bpm=90" "blood.particles=3000" "simulation.gravity=[0,-9.81,0]" \
                     "circulation.valves=pressure" "cycle.segments=[1,2,7]" "model.resolution=1.5"; do
              printf '%s' "$s" > "$corpus/$(printf '%s' "$s" | md5sum | cut -c1-12)"; done ;;
  *) echo "heartsim: no fuzz target $t" >&2; exit 2 ;;
esac
if [ -d "fuzz/regressions/$t" ]; then cp -n "fuzz/regressions/$t"/* "$corpus"/; fi
