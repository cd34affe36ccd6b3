#!/usr/bin/env bash
# Renders a movie's frames and encodes them: the steps of `make movies`.
#
#   scripts/make_movie.sh MOVIE.yaml [OUTPUT_DIR]      (default: output/)
# leaves OUTPUT_DIR/NAME/frame_*.png and OUTPUT_DIR/NAME.mp4, NAME the movie
# file's name without .yaml. FIRSTHIT names the binary (default: build/firsthit).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
[[ $# -ge 1 ]] || { echo "usage: scripts/make_movie.sh MOVIE.yaml [OUTPUT_DIR]" >&2; exit 2; }
movie=$1 outdir=${2:-$here/../output}
name=$(basename "$movie" .yaml)
fps=$("$firsthit" info "$movie" | sed -n 's/^fps: //p')

start=$(date +%s.%N)
rm -rf "${outdir:?}/$name"
"$firsthit" frames "$movie" --out "$outdir/$name"
mid=$(date +%s.%N)
"$here/encode.sh" "$outdir/$name" "$outdir/$name.mp4" --fps "$fps"
end=$(date +%s.%N)
awk -v a="$start" -v b="$mid" -v c="$end" -v n="$name" \
  'BEGIN{printf "%s: render %.1f s, encode %.1f s, total %.1f s\n", n, b-a, c-b, c-a}'
