#!/usr/bin/env bash
# The one AddressSanitizer + UndefinedBehaviorSanitizer build, with clang,
# in build-asan/ (FIRSTHIT_ASAN_BUILD), for x86-64-v2 (the SSE width,
# 16-byte packets): scripts/test_sanitizers.sh runs every test in it and
# scripts/fuzz.sh the loaders' libFuzzer targets (FIRSTHIT_FUZZ=ON), so the
# library is compiled once for both. Clang builds it in about half the time
# GCC took with the same sanitizers (2026-11-28: ~6 against ~11.5 minutes
# on 2 cores for the tests and the fuzzers; scripts/sanitizer_build.sh).
#   bash scripts/build_asan.sh TARGET...
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_ASAN_BUILD:-$here/build-asan}
[[ $# -gt 0 ]] || { echo "usage: scripts/build_asan.sh TARGET..." >&2; exit 2; }
bash "$here/scripts/sanitizer_build.sh" "$build" x86-64-v2 address,undefined -DFIRSTHIT_FUZZ=ON "$@"
