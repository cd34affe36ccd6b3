#!/usr/bin/env bash
# The thread pool, the multi-threaded renders and the frames command under
# ThreadSanitizer: builds the tests in build-tsan/ (-fsanitize=thread) and
# runs the tests that use threads. Any data race fails it.
# The build targets AVX2 (x86-64-v3, 32-byte vectors), so it also runs the
# tracer's own tests at that width: CI covers every width the code has
# (the release build: this machine's widest; the ASan build: SSE, 16 bytes).
#   bash scripts/test_tsan.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_TSAN_BUILD:-$here/build-tsan}
# Clang: a quarter faster to build than GCC with the same sanitizer.
bash "$here/scripts/sanitizer_build.sh" "$build" x86-64-v3 thread firsthit firsthit_tests

# Thread pool; multi-threaded renders giving the same bytes; the frames
# command (one frame per worker, the interrupt watch) run as its own process.
filter='ThreadPool.*:ReportImages.SameBytesForAnyThreadCount:FramesCli.*:Determinism*.*:Interrupt*.*'
export TSAN_OPTIONS="halt_on_error=1 abort_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
cd "$here"
# setarch -R: ThreadSanitizer of GCC 12 / clang 14 cannot map its shadow
# memory under the high mmap randomisation of recent kernels.
run=()
if setarch "$(uname -m)" -R true 2>/dev/null; then run=(setarch "$(uname -m)" -R); fi
# The tracer's tests (geometry, shading, rendering, the robustness battery,
# the report's images) at this build's width.
tracer='Packets.*:Shading.*:FlatScene.*:FastMath*:Intersections*:Accuracy.*:EffectPlan.*:ReportImages.*:Sampler.*'
tracer+=':TileCulling.*:Camera*:Mirrors*:PlaneRobust*:ScaleInvariance*:SelfIntersection*:SphereRobust*'
tracer+=':SpotRobust*:TriangleRobust*:SpotLight.*:RenderCli.*:Bvh*'
# Both sets in one run, shared out among one process a core (gtest's
# sharding): a single process ran on one core for minutes. At most 4: each
# test's thread pool starts a thread a core as well.
shards=$(( $(nproc) < 4 ? $(nproc) : 4 ))
pids=()
trap 'kill "${pids[@]}" 2>/dev/null; exit 130' INT TERM
for ((shard = 0; shard < shards; shard++)); do
  GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard \
    "${run[@]}" "$build/tests/firsthit_tests" --gtest_filter="$filter:$tracer" --gtest_brief=1 \
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
