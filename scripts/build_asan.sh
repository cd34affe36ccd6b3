#!/usr/bin/env bash
# The one AddressSanitizer + UndefinedBehaviorSanitizer build, with clang,
# in build-asan/ (FIRSTHIT_ASAN_BUILD), for x86-64-v2 (the SSE width,
# 16-byte packets): scripts/test_sanitizers.sh runs every test in it and
# scripts/fuzz.sh the loaders' libFuzzer targets (FIRSTHIT_FUZZ=ON), so the
# library is compiled once for both. Clang builds it in about half the time
# GCC took with the same sanitizers (2026-11-28: ~6 against ~11.5 minutes
# on 2 cores for the tests and the fuzzers).
#   bash scripts/build_asan.sh TARGET...
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_ASAN_BUILD:-$here/build-asan}
# FIRSTHIT_NO_FORCED_INLINE (src/core/vec.h): the compiler chooses what to
# inline, which makes this build minutes shorter.
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all -DFIRSTHIT_NO_FORCED_INLINE"

[[ $# -gt 0 ]] || { echo "usage: scripts/build_asan.sh TARGET..." >&2; exit 2; }

mkdir -p "$build"
# A folder an older script configured with GCC starts afresh: told only of
# a new compiler, CMake would drop the other options, sanitizers included.
fresh=()
if [[ -f $build/CMakeCache.txt ]] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang' "$build/CMakeCache.txt"; then
  fresh=(--fresh)
fi
if ! { cmake "${fresh[@]}" -S "$here" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
         -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DFIRSTHIT_ARCH=x86-64-v2 -DFIRSTHIT_FUZZ=ON \
         -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" &&
       cmake --build "$build" -j "$(nproc)" --target "$@"; } >"$build/build.log" 2>&1; then
  echo "build_asan: the build failed; the end of $build/build.log:" >&2
  tail -n 40 "$build/build.log" >&2
  exit 1
fi
grep -q '^CMAKE_CXX_FLAGS:.*-fsanitize=address' "$build/CMakeCache.txt" ||
  { echo "build_asan: $build is not configured with -fsanitize=address" >&2; exit 1; }
