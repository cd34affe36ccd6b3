#!/usr/bin/env bash
# Renders a movie's frames and encodes them: the steps of `make movies`.
#
#   scripts/make_movie.sh MOVIE.yaml [OUTPUT_DIR]      (default: output/)
# leaves OUTPUT_DIR/NAME/frame_*.png and OUTPUT_DIR/NAME.mp4, NAME the movie
# file's name without .yaml. FIRSTHIT names the binary (default: build/firsthit).
#
# The encoder runs while the frames render: firsthit writes each PNG and
# also streams the frames, in order, as raw RGB24 into ffmpeg (encode.sh
# --raw), which gives the same MP4 as encoding the PNGs afterwards.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
[[ $# -ge 1 ]] || { echo "usage: scripts/make_movie.sh MOVIE.yaml [OUTPUT_DIR]" >&2; exit 2; }
movie=$1 outdir=${2:-$here/../output}
name=$(basename "$movie" .yaml)
info=$("$firsthit" info "$movie")
fps=$(sed -n 's/^fps: //p' <<<"$info")
size="$(sed -n 's/^width: //p' <<<"$info")x$(sed -n 's/^height: //p' <<<"$info")"

start=$(date +%s.%N)
rm -rf "${outdir:?}/$name"
mkdir -p "$outdir"
# The movie appears under its name only if both sides succeeded (pipefail):
# a render that fails half-way leaves no half movie.
tmp="$outdir/.$name.mp4.tmp-$$.mp4"
trap 'rm -f "$tmp"' EXIT
"$firsthit" frames "$movie" --out "$outdir/$name" --raw-video - \
  | "$here/encode.sh" --raw "$size" "$tmp" --fps "$fps" >/dev/null
mv -f "$tmp" "$outdir/$name.mp4"
trap - EXIT
end=$(date +%s.%N)
awk -v a="$start" -v b="$end" -v n="$name" -v o="$outdir/$name.mp4" \
  'BEGIN{printf "%s: rendered and encoded into %s in %.1f s\n", n, o, b-a}'
