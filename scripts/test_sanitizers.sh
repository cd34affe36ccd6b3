#!/usr/bin/env bash
# Every test once more under AddressSanitizer and UndefinedBehaviorSanitizer:
# builds firsthit and the tests in build-asan/ (scripts/build_asan.sh: clang,
# x86-64-v2, the SSE width, 16-byte packets) and runs CTest there.
# Any memory error, leak or undefined behaviour fails the test it happens in.
# The slowest loop of the robustness battery (a million rays at the
# tetrahedron's edges) runs a quarter of its rays there. The Slurm test is
# left out: it spends its half minute waiting on the scheduler's daemons,
# and what it runs of firsthit (frames in shards, resumed, then encoded)
# the CLI tests run here too.
#   bash scripts/test_sanitizers.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_ASAN_BUILD:-$here/build-asan}
bash "$here/scripts/build_asan.sh" firsthit firsthit_tests

export ASAN_OPTIONS="abort_on_error=1 detect_stack_use_after_return=1 strict_string_checks=1 ${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1 halt_on_error=1 ${UBSAN_OPTIONS:-}"
cd "$build"
ctest --output-on-failure -j "$(nproc)" -E '^slurm\.'
echo "test_sanitizers: no memory error or undefined behaviour found"
