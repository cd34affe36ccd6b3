#!/usr/bin/env bash
# Frame time against triangle count (make bench-scaling): renders the scene
# family of bench/bench_scaling.cpp -- icospheres of 80 to 1.3 million
# triangles on a floor, 800x800, 1 sample per pixel, a shadowing directional
# light -- on 2 threads, and writes OUT_DIR/scaling.csv and a log-log plot
# OUT_DIR/scaling.png (gnuplot).
#   scripts/bench_scaling.sh [OUT_DIR] [--threads N] [--runs K] [--max-level K]
# BENCH names the benchmark binary (default: build/bench/firsthit_bench_scaling).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bench=${BENCH:-$here/../build/bench/firsthit_bench_scaling}
out=$here/../output
args=(--threads 2 --runs 5)
while [[ $# -gt 0 ]]; do
  case $1 in
    --threads|--runs|--max-level) args+=("$1" "$2"); shift 2 ;;
    *) out=$1; shift ;;
  esac
done
[[ -x $bench ]] || { echo "bench_scaling.sh: $bench is not built (cmake --build build --target firsthit_bench_scaling)" >&2; exit 2; }
mkdir -p "$out"
"$bench" "${args[@]}" | tee "$out/scaling.csv.tmp"
mv "$out/scaling.csv.tmp" "$out/scaling.csv"
if command -v gnuplot >/dev/null; then
  gnuplot <<PLOT
set terminal pngcairo size 900,560 font ",11"
set output '$out/scaling.png'
set datafile separator ','
set title 'Frame time against triangles (800x800, 1 spp, 2 threads, shadows)'
set xlabel 'triangles (log scale)'
set ylabel 'ms (log scale)'
set logscale xy
set grid
set key top left
plot '$out/scaling.csv' skip 1 using 1:5 with linespoints lw 2 pt 7 title 'render (per frame)', \
     '' skip 1 using 1:2 with linespoints lw 2 pt 5 title 'prepare (flatten + BVH, once)'
PLOT
  echo "bench_scaling.sh: $out/scaling.csv, $out/scaling.png"
else
  echo "bench_scaling.sh: $out/scaling.csv (no gnuplot: no plot)"
fi
