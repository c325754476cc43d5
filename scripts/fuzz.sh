#!/usr/bin/env bash
# scripts/fuzz.sh [SECONDS] [TARGET...]: builds the libFuzzer targets (fuzz/, clang with ASan and
# UBSan: the `fuzz` preset) and runs each for SECONDS (default 60) on one core, seeded with the
# built-in scenarios and lessons, the meshes of fuzz/seeds/, a checkpoint of `normal` written by
# the release build (or by $HEARTSIM when set) and the inputs kept in fuzz/regressions/
# (scripts/fuzz-seed.sh). A crash, a sanitizer report or an exception other than a reader's own
# error leaves its input in build/fuzz/findings/<target>/ and makes the script exit non-zero.
# Installs clang and libFuzzer first if they are missing. Each target's log is build/fuzz/TARGET.log;
# its last lines give the inputs run, the coverage (cov: edges, ft: features) and the peak memory.
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
# As scripts/test-sanitized.sh: a UBSan report ends the run (the fuzz preset builds UBSan
# recoverable, so without halt_on_error a report would only be printed).
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
status=0
for t in "${targets[@]}"; do
  corpus=build/fuzz/corpus/$t findings=build/fuzz/findings/$t
  mkdir -p "$findings"
  scripts/fuzz-seed.sh "$t" "$corpus"
  echo "heartsim: fuzzing $t for $seconds s" >&2
  if ! "build/fuzz/fuzz/$t" -max_total_time="$seconds" -artifact_prefix="$findings/" -print_final_stats=1 \
       "$corpus" 2> "build/fuzz/$t.log"; then
    echo "heartsim: $t found a failure: see build/fuzz/$t.log and $findings/" >&2
    status=1
  fi
  grep -E "DONE|stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs" "build/fuzz/$t.log" >&2 || true
done
exit $status
