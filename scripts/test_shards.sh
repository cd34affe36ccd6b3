#!/usr/bin/env bash
# Runs a GoogleTest binary as a few processes at once, each a share of its
# tests (gtest's own sharding: GTEST_TOTAL_SHARDS, GTEST_SHARD_INDEX), from
# the source folder (where CTest runs them too), each shard's log in
# LOGDIR/shardK.log. Fails if any test fails, a shard dies (a sanitizer's
# report, a crash) or runs past the timeout, printing each failed test's
# output and that of the test a shard died in.
#
# Why not CTest for these: it starts the binary once per test, 700 starts,
# and on 2 cores the suite took 88 s that way against 55 s in shards, and
# under AddressSanitizer, whose start-up is slower, 228 s against 170 s
# (2026-11-29, docs/speed.md). CTest still knows every test by name
# (`ctest -R NAME` in build/) and runs the two that are scripts.
#   bash scripts/test_shards.sh BINARY LOGDIR [GTEST_OPTION...]
# FIRSTHIT_TEST_SHARDS: how many (default two a core, at most 4: each
# test's thread pool starts a thread a core too); FIRSTHIT_TEST_TIMEOUT:
# seconds a shard may take (default 1800); FIRSTHIT_TEST_RUNNER: a command
# to start each shard with (scripts/test_tsan.sh: setarch -R).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
[[ $# -ge 2 ]] || { echo "usage: scripts/test_shards.sh BINARY LOGDIR [GTEST_OPTION...]" >&2; exit 2; }
binary=$(realpath "$1") logs=$(realpath -m "$2")
shift 2
[[ -x $binary ]] || { echo "test_shards: $binary is not a program (build it first)" >&2; exit 2; }
cores=$(nproc)
shards=${FIRSTHIT_TEST_SHARDS:-$(( 2 * cores < 4 ? 2 * cores : 4 ))}
timeout=${FIRSTHIT_TEST_TIMEOUT:-1800}
read -r -a runner <<<"${FIRSTHIT_TEST_RUNNER:-}"
mkdir -p "$logs"
cd "$here"
pids=()
trap 'kill "${pids[@]}" 2>/dev/null; exit 130' INT TERM
for ((shard = 0; shard < shards; shard++)); do
  GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard \
    timeout --kill-after=10 "$timeout" "${runner[@]}" "$binary" "$@" \
    >"$logs/shard$shard.log" 2>&1 &
  pids+=($!)
done
status=0 passed=0 skipped=0
for ((shard = 0; shard < shards; shard++)); do
  log=$logs/shard$shard.log
  if wait "${pids[$shard]}"; then
    passed=$(( passed + $(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1) ))
    skipped=$(( skipped + $(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1 | grep . || echo 0) ))
  else
    code=$?
    [[ $code -eq 124 ]] && echo "test_shards: shard $shard of $(basename "$binary") ran past ${timeout} s" >&2
    echo "test_shards: shard $shard of $(basename "$binary") FAILED (exit $code); what failed (the whole log: $log):" >&2
    # Each failed test's lines, and those of the test running when it ended.
    awk '/^\[ RUN      \]/ { block = "" }
         { block = block $0 "\n" }
         /^\[       OK \]|^\[  SKIPPED \] [A-Za-z]/ { block = "" }
         /^\[  FAILED  \] [A-Za-z_].* \([0-9]+ ms\)$/ { printf "%s", block; block = "" }
         END { printf "%s", block }' "$log" | tail -n 400 >&2
    status=1
  fi
done
[[ $status -eq 0 ]] || exit 1
echo "test_shards: $(basename "$binary"): $passed tests passed ($skipped skipped) in $shards shards"
