#!/usr/bin/env bash
# scripts/ci-sanitized.sh: CI's sanitized checks (.ci/run runs it after ./test.sh --long). Builds
# the `asan-ci` preset (clang, AddressSanitizer and UndefinedBehaviorSanitizer, asserts on) with
# only what it runs: the unit tests of the layers pbd, mesh, cardiac, io and viz, run through
# ctest, and the fuzz targets (fuzz/), each run once on every input of its seed corpus
# (scripts/fuzz-seed.sh: the built-in scenarios and lessons, fuzz/seeds/, a checkpoint of `normal`
# and the crashers kept in fuzz/regressions/). Any memory error, leak or undefined behaviour
# fails it. The checkpoint seed is written by $HEARTSIM (CI: build/ci/apps/heartsim, which
# ./test.sh built). The whole sanitized suite stays in scripts/test-sanitized.sh, run by hand
# before a release (docs/reliability.md has both, with their times).
set -euo pipefail
cd "$(dirname "$0")/.."
targets=(fuzz_scenario fuzz_set fuzz_lesson fuzz_checkpoint fuzz_mesh_gmsh fuzz_mesh_tetgen
         fuzz_mesh_vtk fuzz_mesh_surface fuzz_patient_wall)
units=(hs_pbd_tests hs_mesh_tests hs_cardiac_tests hs_io_tests hs_viz_tests)
start=$SECONDS
scripts/install-deps.sh --fuzz
echo "heartsim: sanitized checks: dependencies in $((SECONDS - start)) s" >&2

part=$SECONDS
scripts/build.sh asan-ci "${units[@]}" "${targets[@]}"
echo "heartsim: sanitized checks: build in $((SECONDS - part)) s" >&2

# The options of scripts/test-sanitized.sh: the first report ends the process with a non-zero
# exit; leaks inside libraries heartsim links but does not build (Assimp) are suppressed.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp}
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:strict_string_checks=1:detect_leaks=1}
status=0

part=$SECONDS
# The test preset leaves out what this build does not make (the apps', render's and viewer's
# tests: ctest names them *_NOT_BUILT), the rooms' check, and the tests labelled `long` (the
# scenario keys' extremes: 17 built-ins x 20-step runs, about ten times slower sanitized), which
# the release suite ran.
ctest --preset asan-ci -j "$(nproc)" || status=1
echo "heartsim: sanitized checks: unit tests in $((SECONDS - part)) s" >&2

part=$SECONDS
for t in "${targets[@]}"; do
  corpus=build/asan-ci/corpus/$t log=build/asan-ci/$t.log
  scripts/fuzz-seed.sh "$t" "$corpus"
  inputs=("$corpus"/*)
  t0=$SECONDS
  if "build/asan-ci/fuzz/$t" "${inputs[@]}" > "$log" 2>&1; then
    echo "heartsim: $t: ${#inputs[@]} inputs passed in $((SECONDS - t0)) s" >&2
  else
    echo "heartsim: $t failed on its corpus (build/asan-ci/corpus/$t), its log:" >&2
    tail -40 "$log" >&2
    status=1
  fi
done
echo "heartsim: sanitized checks: fuzz corpora in $((SECONDS - part)) s" >&2
echo "heartsim: sanitized checks: $((SECONDS - start)) s in all" >&2
exit $status
