#!/usr/bin/env bash
# Many objects against Embree 3 (make bench-instances): the bunny on a grid
# receding from the camera (scripts/bunny_grid.sh) at 1, 10, 100, 1,000 and
# 10,000 copies, 800x800, 1 sample, 2 threads, Lambert + ambient + a
# directional light with shadows, in float (Embree's precision), by firsthit
# (`firsthit bench`: load, prepare, frame) and by the Embree peer
# (bench/embree_reference.cpp --placements: the same CSV as Embree
# instances), each with its peak memory; then the forest movie's per-frame
# update (10,000 instances, 1,000-2,000 of them moving) and its frames per
# second against the same forest standing still.
#   scripts/bench_instances.sh [OUT_DIR] [--runs K]
# Writes OUT_DIR/instances.csv (default output/). FIRSTHIT and
# EMBREE_REFERENCE name the programs (defaults: build/firsthit,
# build/bench/firsthit_embree_reference; without the latter its columns are
# empty).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
embree=${EMBREE_REFERENCE:-$here/../build/bench/firsthit_embree_reference}
out=$here/../output runs=9
while [[ $# -gt 0 ]]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    *) out=$1; shift ;;
  esac
done
bash "$here/fetch_meshes.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
peak() { /usr/bin/time -f %M -o "$work/peak" "$@" >"$work/stdout" 2>"$work/stderr" || { cat "$work/stderr" >&2; exit 1; }; }
{
  echo "instances,triangles,firsthit_load_ms,firsthit_prepare_ms,firsthit_ms,firsthit_peak_mb,embree_build_ms,embree_ms,embree_peak_mb"
  for n in 1 10 100 1000 10000; do
    bash "$here/bunny_grid.sh" "$n" "$work" >/dev/null
    peak "$firsthit" bench "$work/grid_$n.yaml" --threads 2 --runs "$runs" --precision float
    row=$(awk -F': ' -v n="$n" -v peak="$(cat "$work/peak")" '{v[$1] = $2}
      END {printf "%s,%d,%.1f,%.1f,%.2f,%.0f", n, 75408 * n, v["load_ms"], v["prepare_ms"], v["ms_per_frame"], peak / 1024}' "$work/stdout")
    if [[ -x $embree ]]; then
      # The bunny the grid's scene places (fetched into this tree), whichever
      # tree the peer was built in.
      peak "$embree" --threads 2 --runs "$runs" --bunny "$here/../animations/meshes/bunny00.off" \
        --placements "$work/grid_$n.csv"
      row+=$(awk -F, -v peak="$(cat "$work/peak")" 'NR == 2 {printf ",%.1f,%.2f,%.0f", $3, $4, peak / 1024}' "$work/stdout")
    else
      row+=",,,"
    fi
    echo "$row"
  done
} | tee "$out/instances.csv.tmp"
mv "$out/instances.csv.tmp" "$out/instances.csv"

# The forest movie: the per-frame update of 10,000 instances, and frames per
# second moving against standing still (the same movie without the wave).
movie=$here/../animations/forest_movie.yaml
"$firsthit" bench "$movie" --frame 60 --threads 2 --runs "$runs" | grep -E '^(instances|frame_update_ms|ms_per_frame):'
grep -v 'surfaces.band' "$movie" | sed "s#^scene: forest.yaml#scene: $here/../animations/forest.yaml#" > "$work/still.yaml"
for m in "$movie" "$work/still.yaml"; do
  fps=$("$firsthit" frames "$m" --out "$work/frames" --quiet --stats --threads 2 | sed -n 's/^frames_per_second: //p')
  rm -rf "$work/frames"
  echo "$( [[ $m == "$movie" ]] && echo moving || echo still )_frames_per_second: $fps"
done
