#!/usr/bin/env bash
# Fuzzes the loaders with libFuzzer (fuzz/) -- scene and movie YAML, glTF
# (JSON and GLB), mesh files (OBJ, PLY, STL, OFF): builds them with
# clang, AddressSanitizer and UBSan in build-fuzz/, then runs each fuzzer for
# SECONDS (default 30) from the seed corpus in tests/fuzz/corpus/. Fails on any
# crash, leak, timeout (10 s for one input) or out-of-memory; the input that
# did it is kept in build-fuzz/artifacts/ (turn it into a regression test in
# tests/yaml/, tests/gltf/ or tests/meshes/). New inputs found go to build-fuzz/corpus/, never into tests/.
#   bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
seconds=${1:-30}
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_FUZZ_BUILD:-$here/build-fuzz}

mkdir -p "$build/artifacts"
if ! { cmake -S "$here" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
         -DFIRSTHIT_FUZZ=ON -DFIRSTHIT_ARCH=x86-64-v2 &&
       cmake --build "$build" -j "$(nproc)" --target scene_fuzzer movie_fuzzer gltf_fuzzer mesh_fuzzer; } >"$build/build.log" 2>&1; then
  echo "fuzz: building the fuzzers failed; the end of $build/build.log:" >&2
  tail -n 40 "$build/build.log" >&2
  exit 1
fi

status=0
# The dictionary and longest input each fuzzer gets.
declare -A dict=([scene]=yaml.dict [movie]=yaml.dict [gltf]=gltf.dict [mesh]=mesh.dict)
declare -A max_len=([scene]=16384 [movie]=16384 [gltf]=65536 [mesh]=16384)
for kind in scene movie gltf mesh; do
  corpus="$build/corpus/$kind"
  mkdir -p "$corpus"
  log="$build/$kind.log"
  echo "fuzz: ${kind}_fuzzer for ${seconds} s (log: $log)"
  if LSAN_OPTIONS="suppressions=$here/fuzz/lsan.supp" "$build/fuzz/${kind}_fuzzer" "$corpus" "$here/tests/fuzz/corpus/$kind" \
       -dict="$here/fuzz/${dict[$kind]}" -max_total_time="$seconds" -timeout=10 \
       -rss_limit_mb=2048 -max_len="${max_len[$kind]}" -print_final_stats=1 \
       -artifact_prefix="$build/artifacts/$kind-" >"$log" 2>&1; then
    grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb' "$log" | sed "s/^/fuzz: $kind: /" || true
    grep -E '^#[0-9]+.*DONE' "$log" | tail -1 | sed "s/^/fuzz: $kind: /" || true
  else
    echo "fuzz: ${kind}_fuzzer FAILED; the end of its log:" >&2
    tail -n 60 "$log" >&2
    status=1
  fi
done
exit $status
