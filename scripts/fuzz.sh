#!/usr/bin/env bash
# Fuzzes the loaders with libFuzzer (fuzz/) -- scene and movie YAML, glTF
# (JSON and GLB), mesh files (OBJ, PLY, STL, OFF): builds them with
# clang, AddressSanitizer and UBSan in build-asan/ (scripts/build_asan.sh,
# shared with the sanitizer tests), then runs each fuzzer for
# SECONDS (default 30) from the seed corpus in tests/fuzz/corpus/. Fails on any
# crash, leak, timeout (10 s for one input) or out-of-memory; the input that
# did it is kept in build-asan/artifacts/ (turn it into a regression test in
# tests/yaml/, tests/gltf/ or tests/meshes/). New inputs found go to build-asan/corpus/, never into tests/.
#   bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
seconds=${1:-30}
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FIRSTHIT_ASAN_BUILD:-$here/build-asan}

bash "$here/scripts/build_asan.sh" scene_fuzzer movie_fuzzer gltf_fuzzer mesh_fuzzer
mkdir -p "$build/artifacts"

# The dictionary and longest input each fuzzer gets.
declare -A dict=([scene]=yaml.dict [movie]=yaml.dict [gltf]=gltf.dict [mesh]=mesh.dict)
declare -A max_len=([scene]=16384 [movie]=16384 [gltf]=65536 [mesh]=16384)
kinds=(scene movie gltf mesh)
fuzz_one() {  # KIND: runs its fuzzer in place of the (background) shell; its log in $build/KIND.log
  local kind=$1
  mkdir -p "$build/corpus/$kind"
  LSAN_OPTIONS="suppressions=$here/fuzz/lsan.supp" exec "$build/fuzz/${kind}_fuzzer" "$build/corpus/$kind" \
    "$here/tests/fuzz/corpus/$kind" -dict="$here/fuzz/${dict[$kind]}" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -max_len="${max_len[$kind]}" -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$kind-" >"$build/$kind.log" 2>&1
}
# One fuzzer a core at a time; their reports in a fixed order.
at_once=$(( $(nproc) < ${#kinds[@]} ? $(nproc) : ${#kinds[@]} ))
echo "fuzz: ${kinds[*]} for ${seconds} s each, $at_once at a time (logs: $build/KIND.log)"
declare -A pid
trap 'kill "${pid[@]}" 2>/dev/null; exit 130' INT TERM
status=0
report() {  # KIND: waits for it, then says how it went
  local kind=$1 log="$build/$1.log"
  if wait "${pid[$kind]}"; then
    grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb' "$log" | sed "s/^/fuzz: $kind: /" || true
    grep -E '^#[0-9]+.*DONE' "$log" | tail -1 | sed "s/^/fuzz: $kind: /" || true
  else
    echo "fuzz: ${kind}_fuzzer FAILED; the end of its log:" >&2
    tail -n 60 "$log" >&2
    status=1
  fi
}
for ((i = 0; i < ${#kinds[@]}; i++)); do
  fuzz_one "${kinds[$i]}" &
  pid[${kinds[$i]}]=$!
  done_one=$((i + 1 - at_once))
  if ((done_one >= 0)); then report "${kinds[$done_one]}"; fi
done
for ((i = ${#kinds[@]} - at_once + 1; i < ${#kinds[@]}; i++)); do
  ((i >= 0)) && report "${kinds[$i]}"
done
exit $status
