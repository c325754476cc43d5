#!/usr/bin/env bash
# scripts/fuzz.sh [SECONDS] [TARGET...]: builds the libFuzzer targets (fuzz/, clang with ASan and
# UBSan: the `fuzz` preset) and runs each for SECONDS (default 60) on one core, seeded with the
# built-in scenarios and lessons, the meshes of fuzz/seeds/, and with a checkpoint of `normal`
# written by the release build (or by $HEARTSIM when set). A crash leaves its input in
# build/fuzz/findings/<target>/ and makes the script exit non-zero. Installs clang and libFuzzer first if they are missing.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(fuzz_scenario fuzz_set fuzz_lesson fuzz_checkpoint
                                     fuzz_mesh_gmsh fuzz_mesh_tetgen fuzz_mesh_vtk fuzz_mesh_surface
                                     fuzz_patient_wall)
scripts/install-deps.sh --fuzz
cmake --preset fuzz >&2  # every time: a target added to fuzz/ since the last configure
scripts/build.sh fuzz "${targets[@]}"
# Leaks inside libraries heartsim links but does not build (Assimp's readers on malformed
# files) are suppressed as in scripts/test-sanitized.sh; heartsim's own are still found.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp}
status=0
for t in "${targets[@]}"; do
  corpus=build/fuzz/corpus/$t findings=build/fuzz/findings/$t
  mkdir -p "$corpus" "$findings"
  case $t in
    fuzz_scenario) cp -n scenarios/*.toml "$corpus"/ ;;
    fuzz_lesson) cp -n lessons/*.toml "$corpus"/ ;;
    fuzz_mesh_*) cp -n fuzz/seeds/"$t"/* "$corpus"/ ;;  # a marked 6-tet box in each format (tests/io/mesh_writers.h)
    fuzz_patient_wall) cp -n fuzz/seeds/"$t"/* "$corpus"/ ;;  # biv-me's endocardium (first byte: obj, coarse)
    fuzz_checkpoint)  # two checkpoints of `normal`: without and with the run monitor's state
      if [ ! -f "$corpus/normal-run.hsck" ]; then
        heartsim=${HEARTSIM:-build/release/apps/heartsim}
        [ -n "${HEARTSIM:-}" ] || scripts/build.sh release heartsim
        seed=build/fuzz/seed
        "$heartsim" run normal --duration 0.004 --checkpoint-every 0.002 --out "$seed" >/dev/null
        cp "$seed/$(ls "$seed" | grep hsck | tail -1)" "$corpus/normal-run.hsck"
      fi ;;
    fuzz_set) for s in "cycle.heart_rate_bpm=90" "blood.particles=3000" "simulation.gravity=[0,-9.81,0]" \
                       "circulation.valves=pressure" "cycle.segments=[1,2,7]" "model.resolution=1.5"; do
                printf '%s' "$s" > "$corpus/$(printf '%s' "$s" | md5sum | cut -c1-12)"; done ;;
  esac
  echo "heartsim: fuzzing $t for $seconds s" >&2
  if ! "build/fuzz/fuzz/$t" -max_total_time="$seconds" -artifact_prefix="$findings/" -print_final_stats=1 \
       "$corpus" 2> "build/fuzz/$t.log"; then
    echo "heartsim: $t found a failure: see build/fuzz/$t.log and $findings/" >&2
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs" "build/fuzz/$t.log" >&2 || true
done
exit $status
