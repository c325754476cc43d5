#!/usr/bin/env bash
# scripts/test-sanitized.sh [CTEST ARGS...]: the whole test suite again, built with
# AddressSanitizer and UndefinedBehaviorSanitizer (the `asan` preset: optimised, asserts on).
# Any memory error, leak or undefined behaviour aborts the test that met it, so ctest fails.
# It takes about 85 minutes on two cores (the build 31, the suite 54), so it is run by hand
# before a release and after changes to memory handling, not by .ci/run (docs/reliability.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh asan
# halt_on_error: the first report ends the process with a non-zero exit (UBSan is built with
# -fno-sanitize-recover, so it always does); print_stacktrace: UBSan says where.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp}
checks=halt_on_error=1:strict_string_checks=1
# The tests that draw through Mesa's EGL: Mesa keeps its screen allocated for the process's
# life and has no frame pointers, so LeakSanitizer cannot tell its leak from heartsim's
# (a suppression needs fast_unwind_on_malloc=0, with which these tests run past 25 minutes).
# They run with every ASan and UBSan check but the leak check; every other test with it.
drawing='^(Offscreen|CliRender|ViewUnderXvfb|LessonUnderXvfb)'
status=0
ASAN_OPTIONS=${ASAN_OPTIONS:-$checks:detect_leaks=1} ctest --preset asan -j "$(nproc)" -E "$drawing" "$@" || status=1
ASAN_OPTIONS=${ASAN_OPTIONS:-$checks:detect_leaks=0} ctest --preset asan -j "$(nproc)" -R "$drawing" "$@" || status=1
exit $status
