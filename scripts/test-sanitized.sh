#!/usr/bin/env bash
# scripts/test-sanitized.sh [CTEST ARGS...]: the whole test suite again, built with
# AddressSanitizer and UndefinedBehaviorSanitizer (the `asan` preset: optimised, asserts on).
# Any memory error, leak or undefined behaviour aborts the test that met it, so ctest fails.
# It takes about an hour on two cores (the build 25 min, the suite 30), so it is run by hand
# before a release and after changes to memory handling, not by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh asan
# halt_on_error: the first report ends the process with a non-zero exit (UBSan is built with
# -fno-sanitize-recover, so it always does); print_stacktrace: UBSan says where.
# fast_unwind_on_malloc=0: Mesa has no frame pointers, and the suppressions need its frames.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:strict_string_checks=1:fast_unwind_on_malloc=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp}
ctest --preset asan -j "$(nproc)" "$@"
