#!/usr/bin/env bash
# Every test once more under AddressSanitizer and UndefinedBehaviorSanitizer:
# builds firsthit and the tests in build-asan/ (for x86-64-v2: the SSE width,
# 16-byte packets) and runs CTest there.
# Any memory error, leak or undefined behaviour fails the test it happens in.
# The slowest loop of the robustness battery (a million rays at the
# tetrahedron's edges) runs a quarter of its rays there.
#   bash scripts/test_sanitizers.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_ASAN_BUILD:-$here/build-asan}
# FIRSTHIT_NO_FORCED_INLINE (src/core/vec.h): the compiler chooses what to
# inline, which makes this build minutes shorter.
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all -DFIRSTHIT_NO_FORCED_INLINE"

mkdir -p "$build"
if ! { cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DFIRSTHIT_ARCH=x86-64-v2 \
         -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" &&
       cmake --build "$build" -j "$(nproc)" --target firsthit firsthit_tests; } >"$build/build.log" 2>&1; then
  echo "test_sanitizers: the build failed; the end of $build/build.log:" >&2
  tail -n 40 "$build/build.log" >&2
  exit 1
fi

export ASAN_OPTIONS="abort_on_error=1 detect_stack_use_after_return=1 strict_string_checks=1 ${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1 halt_on_error=1 ${UBSAN_OPTIONS:-}"
cd "$build"
ctest --output-on-failure -j "$(nproc)"
echo "test_sanitizers: no memory error or undefined behaviour found"
