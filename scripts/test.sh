#!/usr/bin/env bash
# Runs every test: sets up (installs what is missing, builds), then the
# tests -- at each x86-64 level the binary has, then under the sanitizers,
# then the fuzzers.
#   bash scripts/test.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
cd "$here/build"
# Everything else: the tests, the Embree peer, the benchmarks; and the
# micro-benchmarks, built only when asked for (bench/CMakeLists.txt):
# compiled here, not run, so that they keep up with the tracer.
cmake --build . --target all firsthit_bench -j "$(nproc)"
# The GoogleTest binary in shards (scripts/test_shards.sh: a few processes
# rather than one per test), and beside it CTest's two tests that are
# scripts, which spend most of their time waiting: the Slurm cluster's and
# the window's.
ctest --output-on-failure -R '^(slurm|view)\.' >ctest-scripts.log 2>&1 &
scripts=$!
# (On a failure, the scripts' tests end first: no Slurm daemons left behind.)
bash "$here/scripts/test_shards.sh" tests/firsthit_tests test-logs || { wait "$scripts" || true; exit 1; }
if ! wait "$scripts"; then cat ctest-scripts.log >&2; exit 1; fi
grep -E "tests passed|skipped" ctest-scripts.log | sed 's/^/test: the scripts: /' || true
# The same tests again through each lower x86-64 level this CPU runs, forced
# (FIRSTHIT_ISA, src/render/levels.h): the one binary's copies of the tracer
# for v2 and v3. Once only: the Slurm and window tests, which render nothing
# new, and the encoders' (video/, scripts/encode.sh, make movies), which
# no level changes -- the frames they encode are the other tests' to check.
widest=$(./firsthit --version | sed -n 's/.*tracing at x86-64-v\([0-9]\).*/\1/p')
for ((level = 2; level < ${widest:-2}; level++)); do
  echo "test: every test again at x86-64-v$level (FIRSTHIT_ISA=v$level)"
  FIRSTHIT_ISA=v$level bash "$here/scripts/test_shards.sh" tests/firsthit_tests "test-logs/v$level" \
    --gtest_filter='-EncodeCli.*:EncodeScript.*:MakeMovies.*:Yuv420.*'
done
# ThreadSanitizer over the tests that start threads and the tracer's tests
# at the AVX2 width (build-tsan); every test once more under
# AddressSanitizer and UndefinedBehaviorSanitizer, then the loaders' fuzzers
# for 15 s each (one clang build for both: build-asan).
bash "$here/scripts/test_tsan.sh"
bash "$here/scripts/test_sanitizers.sh"
bash "$here/scripts/fuzz.sh" 15
