#!/usr/bin/env bash
# Runs every test: sets up (installs what is missing, builds), then CTest.
#   bash scripts/test.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
cd "$here/build"
ctest --output-on-failure -j "$(nproc)"
# ThreadSanitizer over the threaded tests and, built for AVX2, the tracer's
# tests at that width; then the loaders' fuzzers
# for 15 s each (each builds in its own folder: build-tsan, build-fuzz).
bash "$here/scripts/test_tsan.sh"
bash "$here/scripts/fuzz.sh" 15
# Every test once more under AddressSanitizer and
# UndefinedBehaviorSanitizer (builds in build-asan).
bash "$here/scripts/test_sanitizers.sh"
