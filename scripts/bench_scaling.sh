#!/usr/bin/env bash
# Frame time against triangle count (make bench-scaling): renders the scene
# family of bench/bench_scaling.cpp -- icospheres of 80 to 1.3 million
# triangles on a floor, 800x800, 1 sample per pixel, a shadowing directional
# light -- on 2 threads, and writes OUT_DIR/scaling.csv and a log-log plot
# OUT_DIR/scaling.png (gnuplot); the same family in float (Embree's
# precision, the like-for-like comparison) into OUT_DIR/scaling_float.csv.
#   scripts/bench_scaling.sh [OUT_DIR] [--threads N] [--runs K] [--max-level K]
# Then the same for real meshes from Debian's package data (scripts/
# fetch_meshes.sh), through `firsthit bench`: OUT_DIR/scaling_real.csv.
# Then, when it is built, the Embree 3 peer (bench/embree_reference.cpp: the
# same scenes, rays and shading, the widest packets Embree traces natively:
# 16 rays with AVX-512, 8 with AVX2) with the same --threads,
# --runs and --max-level: OUT_DIR/scaling_embree.csv, a third curve and the
# bunny's point on the plot. Without it, the rest runs as before.
# BENCH names the benchmark binary (default: build/bench/firsthit_bench_scaling),
# FIRSTHIT the renderer (default: build/firsthit), EMBREE_REFERENCE the
# Embree peer (default: build/bench/firsthit_embree_reference).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bench=${BENCH:-$here/../build/bench/firsthit_bench_scaling}
firsthit=${FIRSTHIT:-$here/../build/firsthit}
embree=${EMBREE_REFERENCE:-$here/../build/bench/firsthit_embree_reference}
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
"$bench" "${args[@]}" --precision float | tee "$out/scaling_float.csv.tmp"
mv "$out/scaling_float.csv.tmp" "$out/scaling_float.csv"

# Real meshes: the bunny (and whatever scene files name fetched meshes).
bash "$here/fetch_meshes.sh"
threads=2
for ((i = 0; i < ${#args[@]}; i += 2)); do [[ ${args[i]} == --threads ]] && threads=${args[i+1]}; done
{
  echo "scene,triangles,load_ms,prepare_ms,build_ms,bvh_nodes,render_ms,rays_per_second"
  for scene in "$here/../animations/bunny.yaml"; do
    tris=$("$firsthit" info "$scene" | sed -n 's/^triangles: //p')
    "$firsthit" bench "$scene" --runs 9 --threads "$threads" |
      awk -F': ' -v s="$(basename "$scene" .yaml)" -v t="$tris" '
        {v[$1] = $2}
        END {print s "," t "," v["load_ms"] "," v["prepare_ms"] "," v["build_ms"] "," v["bvh_nodes"] "," v["ms_per_frame"] "," v["rays_per_second"]}'
  done
} | tee "$out/scaling_real.csv.tmp"
mv "$out/scaling_real.csv.tmp" "$out/scaling_real.csv"

# The Embree 3 peer, if built: icosphere rows, then the bunny's.
have_embree=0
if [[ -x $embree ]]; then
  "$embree" "${args[@]}" --bunny "$here/../animations/meshes/bunny00.off" | tee "$out/scaling_embree.csv.tmp"
  mv "$out/scaling_embree.csv.tmp" "$out/scaling_embree.csv"
  have_embree=1
else
  echo "bench_scaling.sh: no Embree reference ($embree is not built: apt-get install libembree-dev, reconfigure," \
       "cmake --build build --target firsthit_embree_reference); plotting firsthit alone" >&2
fi
embree_plot=""
if [[ $have_embree == 1 ]]; then
  embree_plot=", \\
     '$out/scaling_embree.csv' skip 1 using 2:(strcol(1) eq 'bunny' ? 1/0 : \$4) with linespoints lw 2 pt 13 title 'Embree 3, native packets: render (per frame)', \\
     '' skip 1 using 2:(strcol(1) eq 'bunny' ? \$4 : 1/0) with points pt 13 ps 2 title 'Stanford bunny: Embree 3 render'"
fi
# Growth from 10^3 to 10^6 triangles (the rows of 1,280 and 1,310,720), time
# and, where counted, instructions a frame: the work against the waits.
growth() {  # CSV, label, triangles column, time column, instructions column (0: none)
  awk -F, -v label="$2" -v tc="$3" -v mc="$4" -v ic="$5" '
    $tc == 1280 {t0 = $mc; i0 = ic ? $ic : ""}
    $tc == 1310720 {t1 = $mc; i1 = ic ? $ic : ""}
    END {
      if (t0 == "" || t1 == "") exit
      line = sprintf("bench_scaling.sh: 1,280 -> 1,310,720 triangles, %s: time x%.2f", label, t1 / t0)
      if (i0 != "" && i1 != "") line = line sprintf(", instructions x%.2f", i1 / i0)
      print line
    }' "$1"
}
growth "$out/scaling.csv" "firsthit double" 1 5 8
growth "$out/scaling_float.csv" "firsthit float" 1 5 8
[[ $have_embree == 1 ]] && growth "$out/scaling_embree.csv" "Embree 3" 2 4 0

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
plot '$out/scaling.csv' skip 1 using 1:5 with linespoints lw 2 pt 7 title 'icospheres: render (per frame, double)', \
     '$out/scaling_float.csv' skip 1 using 1:5 with linespoints lw 2 pt 6 title 'icospheres: render (per frame, float)', \
     '' skip 1 using 1:2 with linespoints lw 2 pt 5 title 'icospheres: prepare (flatten + BVH, once)', \
     '$out/scaling_real.csv' skip 1 using 2:7 with points pt 9 ps 2 title 'Stanford bunny: render', \
     '' skip 1 using 2:4 with points pt 11 ps 2 title 'Stanford bunny: prepare'$embree_plot
PLOT
  echo "bench_scaling.sh: $out/scaling.csv, $out/scaling_float.csv, $out/scaling_real.csv$([[ $have_embree == 1 ]] && echo ", $out/scaling_embree.csv"), $out/scaling.png"
else
  echo "bench_scaling.sh: $out/scaling.csv, $out/scaling_float.csv$([[ $have_embree == 1 ]] && echo ", $out/scaling_embree.csv") (no gnuplot: no plot)"
fi
