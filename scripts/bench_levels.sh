#!/usr/bin/env bash
# The dispatching binary against builds made for one x86-64 level alone
# (make bench-levels): the report's Movie 1 and Movie 2 frames and the
# bunny, 2 threads, with FIRSTHIT_ISA forcing each level this CPU runs,
# each against the build for that level (FIRSTHIT_ARCH=x86-64-vN; `host`
# for the CPU's own). Timed in turns, ROUNDS rounds of `firsthit bench
# --runs 9`, each keeping its fastest round's median.
#   scripts/bench_levels.sh [OUT_DIR] [--rounds N]
# FIRSTHIT names the dispatching binary (default build/firsthit); the
# one-level builds are made in build-level-vN/ (and build-level-host/) when
# missing. Writes OUT_DIR/levels.txt (default output/) as key: value lines.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
firsthit=${FIRSTHIT:-$here/build/firsthit}
out=$here/output rounds=3
while [[ $# -gt 0 ]]; do
  case $1 in
    --rounds) rounds=$2; shift 2 ;;
    *) out=$1; shift ;;
  esac
done
widest=$("$firsthit" --version | sed -n 's/.*tracing at x86-64-v\([0-9]\).*/\1/p')
[[ -n $widest ]] || { echo "bench_levels: $firsthit is not a dispatching build" >&2; exit 1; }
# The build for one level (arch: x86-64-vN or host), made once.
one_level() {
  local arch=$1 dir=$here/build-level-${1#x86-64-}
  if [[ ! -x $dir/firsthit ]]; then
    echo "bench_levels: building FIRSTHIT_ARCH=$arch in $dir" >&2
    cmake -S "$here" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DFIRSTHIT_ARCH="$arch" >/dev/null
    cmake --build "$dir" -j "$(nproc)" --target firsthit >/dev/null
  fi
  echo "$dir/firsthit"
}
declare -A alone
for ((level = 2; level < widest; level++)); do alone[$level]=$(one_level x86-64-v$level); done
alone[$widest]=$(one_level host)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenes="movie1 movie2 bunny"
ms() { "$@" --threads 2 --runs 9 | sed -n 's/^ms_per_frame: //p'; }
keep_min() { awk -v a="$2" -v f="$1" 'BEGIN {b = 1e9; if ((getline l < f) > 0) b = l; print (a < b ? a : b) > f}'; }
for ((r = 0; r < rounds; r++)); do
  for s in $scenes; do
    for ((level = 2; level <= widest; level++)); do
      keep_min "$work/dispatch_v${level}_$s" "$(FIRSTHIT_ISA=v$level ms "$firsthit" bench "$here/animations/$s.yaml")"
      keep_min "$work/alone_v${level}_$s" "$(ms "${alone[$level]}" bench "$here/animations/$s.yaml")"
    done
  done
done
mkdir -p "$out"
{
  echo "cpu_level: x86-64-v$widest"
  echo "dispatch_size_bytes: $(stat -c %s "$firsthit")"
  echo "host_size_bytes: $(stat -c %s "${alone[$widest]}")"
  for s in $scenes; do
    for ((level = 2; level <= widest; level++)); do
      d=$(cat "$work/dispatch_v${level}_$s") a=$(cat "$work/alone_v${level}_$s")
      echo "${s}_v${level}_dispatch_ms: $d"
      echo "${s}_v${level}_alone_ms: $a"
      awk -v d="$d" -v a="$a" -v k="${s}_v${level}_ratio" 'BEGIN {printf "%s: %.3f\n", k, d / a}'
    done
  done
} | tee "$out/levels.txt"
