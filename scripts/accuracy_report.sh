#!/usr/bin/env bash
# What accuracy costs, for frame 0 of both movies: OUT/accuracy_movie1.csv and
# .png, OUT/accuracy_movie2.csv and .png (firsthit accuracy; gnuplot plots).
#
#   scripts/accuracy_report.sh [OUT_DIR]      (default: output/)
# FIRSTHIT names the binary (default: build/firsthit).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
firsthit=${FIRSTHIT:-$root/build/firsthit}
out=$(mkdir -p "${1:-$root/output}" && cd "${1:-$root/output}" && pwd)
cd "$root"  # so the plots' titles name animations/movieN.yaml
command -v gnuplot >/dev/null || { echo "accuracy_report.sh: error: gnuplot not found; install it with: apt-get install gnuplot-nox" >&2; exit 2; }
for movie in movie1 movie2; do
  "$firsthit" accuracy "animations/$movie.yaml" --frame 0 \
    --csv "$out/accuracy_$movie.csv" --plot "$out/accuracy_$movie.png"
  echo "accuracy_report.sh: $out/accuracy_$movie.csv, $out/accuracy_$movie.png"
done
