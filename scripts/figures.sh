#!/usr/bin/env bash
# The report's figure ladder (docs/model.md section 6): renders animations/figures/
# figure1..6.yaml, times each with `firsthit bench` (median of 7 runs), and
# writes what each effect costs: OUT/figureN.png, OUT/figures.md (a table of
# effects, time and rays by kind) and OUT/figures_grid.png (all six, labelled).
#
#   scripts/figures.sh [OUT_DIR]      (default: output/figures)
# FIRSTHIT names the binary (default: build/firsthit).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$here/..
firsthit=${FIRSTHIT:-$root/build/firsthit}
out=${1:-$root/output/figures}
mkdir -p "$out"

key() { sed -n "s/^$1: //p" "$2"; }

table=$out/figures.md
{
  echo "| figure | effects simulated | ms per frame (2 threads) | primary rays | shadow rays | reflection rays |"
  echo "|---|---|---:|---:|---:|---:|"
} >"$table.tmp"
for n in 1 2 3 4 5 6; do
  scene=$root/animations/figures/figure$n.yaml
  "$firsthit" render "$scene" --stats -o "$out/figure$n.png" >"$out/figure$n.stats"
  "$firsthit" bench "$scene" --runs 7 >"$out/figure$n.bench"
  s=$out/figure$n.bench
  printf "| %s | %s | %.1f | %s | %s | %s |\n" "$n" "$(key effects "$s")" "$(key ms_per_frame "$s")" \
    "$(key rays.primary "$s")" "$(key rays.shadow "$s")" "$(key rays.reflection "$s")" >>"$table.tmp"
done
mv "$table.tmp" "$table"
cat "$table"

if command -v ffmpeg >/dev/null; then
  ffmpeg -hide_banner -loglevel error -y -start_number 1 -i "$out/figure%d.png" \
    -vf "drawtext=text='figure %{eif\:n+1\:d}':x=10:y=10:fontsize=40:fontcolor=white:box=1:boxcolor=black@0.5,scale=320:-1,tile=3x2:padding=4:color=white" \
    -frames:v 1 -update 1 "$out/figures_grid.png"
  echo "grid: $out/figures_grid.png"
fi
