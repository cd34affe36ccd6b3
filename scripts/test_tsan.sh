#!/usr/bin/env bash
# The thread pool, the multi-threaded renders and the frames command under
# ThreadSanitizer, and the tracer's own tests at the AVX2 width (x86-64-v3,
# 32-byte vectors): builds firsthit and firsthit_tracer_tests (the tracer's
# tests and the command-line tests that start threads, tests/CMakeLists.txt)
# in build-tsan/ (-fsanitize=thread) and runs them. Any data race fails it.
# With the release build (this machine's widest level) and the ASan build
# (SSE, 16 bytes), CI runs the tracer's insides at every width it has.
#   bash scripts/test_tsan.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_TSAN_BUILD:-$here/build-tsan}
# Clang: a quarter faster to build than GCC with the same sanitizer.
bash "$here/scripts/sanitizer_build.sh" "$build" x86-64-v3 thread firsthit firsthit_tracer_tests

export TSAN_OPTIONS="halt_on_error=1 abort_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
# setarch -R: ThreadSanitizer of GCC 12 / clang 14 cannot map its shadow
# memory under the high mmap randomisation of recent kernels.
if setarch "$(uname -m)" -R true 2>/dev/null; then export FIRSTHIT_TEST_RUNNER="setarch $(uname -m) -R"; fi
# In shards, a process a share of the tests (scripts/test_shards.sh).
bash "$here/scripts/test_shards.sh" "$build/tests/firsthit_tracer_tests" "$build/test-logs"
echo "test_tsan: no data race found"
