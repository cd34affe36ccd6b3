#!/usr/bin/env bash
# One clang build with sanitizers, for the scripts that run one
# (build_asan.sh: AddressSanitizer + UBSan, for the tests and the fuzzers;
# test_tsan.sh: ThreadSanitizer): configures FOLDER for one x86-64 LEVEL,
# builds the TARGETs there, its log in FOLDER/build.log, and checks that the
# cache holds the sanitizers. Any -D option among the arguments goes to CMake.
# Clang builds with sanitizers in a half (ASan + UBSan) to three quarters
# (TSan) of GCC's time on 2 cores (2026-11-28).
#   bash scripts/sanitizer_build.sh FOLDER LEVEL SANITIZERS [-DOPTION=VALUE...] TARGET...
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
[[ $# -ge 4 ]] || { echo "usage: scripts/sanitizer_build.sh FOLDER LEVEL SANITIZERS [-DOPTION=VALUE...] TARGET..." >&2; exit 2; }
build=$1 level=$2 sanitizers=$3
shift 3
options=() targets=()
for arg; do
  if [[ $arg == -D* ]]; then options+=("$arg"); else targets+=("$arg"); fi
done
[[ ${#targets[@]} -gt 0 ]] || { echo "sanitizer_build: no target to build" >&2; exit 2; }
# FIRSTHIT_NO_FORCED_INLINE (src/core/vec.h): the compiler chooses what to
# inline, which makes these builds minutes shorter.
flags="-fsanitize=$sanitizers -fno-sanitize-recover=all -fno-omit-frame-pointer -DFIRSTHIT_NO_FORCED_INLINE"

mkdir -p "$build"
# A folder an older script configured with GCC starts afresh: told only of
# a new compiler, CMake would drop the other options, sanitizers included.
fresh=()
if [[ -f $build/CMakeCache.txt ]] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang' "$build/CMakeCache.txt"; then
  fresh=(--fresh)
fi
if ! { cmake "${fresh[@]}" -S "$here" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
         -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DFIRSTHIT_ARCH="$level" "${options[@]}" \
         -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=$sanitizers" &&
       cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"; } >"$build/build.log" 2>&1; then
  echo "$(basename "$build"): the build failed; the end of $build/build.log:" >&2
  tail -n 40 "$build/build.log" >&2
  exit 1
fi
grep -q "^CMAKE_CXX_FLAGS:.*-fsanitize=$sanitizers" "$build/CMakeCache.txt" ||
  { echo "$(basename "$build"): $build is not configured with -fsanitize=$sanitizers" >&2; exit 1; }
