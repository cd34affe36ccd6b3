#!/usr/bin/env bash
# Every test once more under AddressSanitizer and UndefinedBehaviorSanitizer:
# builds firsthit and the tests in build-asan/ (scripts/build_asan.sh: clang,
# x86-64-v2, the SSE width, 16-byte packets) and runs them there.
# Any memory error, leak or undefined behaviour fails the run: the report
# follows the test it happened in, a leak's ends its shard.
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
# The test binary in shards (scripts/test_shards.sh), the window's test
# beside it.
(cd "$build" && ctest --output-on-failure -R '^view\.' >ctest-scripts.log 2>&1) &
window=$!
bash "$here/scripts/test_shards.sh" "$build/tests/firsthit_tests" "$build/test-logs" || { wait "$window" || true; exit 1; }
if ! wait "$window"; then cat "$build/ctest-scripts.log" >&2; exit 1; fi
echo "test_sanitizers: no memory error or undefined behaviour found"
