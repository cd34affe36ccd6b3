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
cd "$here"
# setarch -R: ThreadSanitizer of GCC 12 / clang 14 cannot map its shadow
# memory under the high mmap randomisation of recent kernels.
run=()
if setarch "$(uname -m)" -R true 2>/dev/null; then run=(setarch "$(uname -m)" -R); fi
# Shared out among one process a core (gtest's sharding). At most 4: each
# test's thread pool starts a thread a core as well.
shards=$(( $(nproc) < 4 ? $(nproc) : 4 ))
pids=()
trap 'kill "${pids[@]}" 2>/dev/null; exit 130' INT TERM
for ((shard = 0; shard < shards; shard++)); do
  GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard \
    "${run[@]}" "$build/tests/firsthit_tracer_tests" --gtest_brief=1 \
    >"$build/shard$shard.log" 2>&1 &
  pids+=($!)
done
status=0
for ((shard = 0; shard < shards; shard++)); do
  if wait "${pids[$shard]}"; then
    grep -E '^\[ *PASSED' "$build/shard$shard.log" | sed "s/^/test_tsan: shard $shard: /" || true
  else
    echo "test_tsan: shard $shard FAILED; the end of its log:" >&2
    tail -n 80 "$build/shard$shard.log" >&2
    status=1
  fi
done
[[ $status -eq 0 ]] || exit 1
echo "test_tsan: no data race found"
