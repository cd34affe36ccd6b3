#!/usr/bin/env bash
# Renders a movie's frames and encodes them: the steps of `make movies`.
#
#   scripts/make_movie.sh MOVIE.yaml [OUTPUT_DIR] [--encoder-threads N] [--raw-pix-fmt P] [--quiet]
# leaves OUTPUT_DIR/NAME/frame_*.png and OUTPUT_DIR/NAME.mp4 (OUTPUT_DIR: output/ in
# the current folder, not the script's), NAME the movie
# file's name without .yaml. FIRSTHIT names the binary (default: build/firsthit).
#   --encoder-threads N   x264's threads (encode.sh --threads); default: all cores
#   --raw-pix-fmt P       the streamed frames' pixels: rgb24 (default) or
#                         yuv420p, converted by firsthit on its render
#                         threads instead of by ffmpeg (`make movies`)
#   --quiet               no progress line while the frames render
#
# The encoder runs while the frames render: firsthit writes each PNG and
# also streams the frames, in order, as raw video into ffmpeg (encode.sh
# --raw). In RGB24 that gives the same MP4 as encoding the PNGs afterwards
# with as many encoder threads; in yuv420p the chroma is firsthit's 2x2 mean
# (src/video/yuv420.h), within a few levels of ffmpeg's.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
usage="usage: scripts/make_movie.sh MOVIE.yaml [OUTPUT_DIR] [--encoder-threads N] [--raw-pix-fmt P] [--quiet]"
positional=() encode_options=() frames_options=()
die() { echo "make_movie.sh: error: $*" >&2; exit 2; }
# Everything is checked -- options, then the movie, every frame of it (firsthit
# info) -- before the old frames are touched: a mistake once left the last
# good render's folder half emptied.
while [[ $# -gt 0 ]]; do
  case $1 in
    --encoder-threads)
      [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || die "--encoder-threads needs a whole number > 0, got '${2:-}'"
      encode_options+=(--threads "$2"); shift 2 ;;
    --raw-pix-fmt)
      [[ $# -ge 2 && ($2 == rgb24 || $2 == yuv420p) ]] || die "--raw-pix-fmt is rgb24 or yuv420p, got '${2:-}'"
      frames_options+=(--raw-pix-fmt "$2"); encode_options+=(--pix-fmt "$2"); shift 2 ;;
    --quiet) frames_options+=(--quiet); shift ;;
    -*) echo "make_movie.sh: error: unknown option '$1'" >&2; echo "$usage" >&2; exit 2 ;;
    *) positional+=("$1"); shift ;;
  esac
done
[[ ${#positional[@]} -ge 1 && ${#positional[@]} -le 2 ]] || { echo "$usage" >&2; exit 2; }
movie=${positional[0]} outdir=${positional[1]:-output}
name=$(basename "$movie")
name=${name%.*}  # movie.yaml, model.gltf, model.glb: the name without its extension
info=$("$firsthit" info "$movie")  # its one line on a mistake, then exit 2
fps=$(sed -n 's/^fps: //p' <<<"$info")
[[ -n $fps ]] || die "$movie is a scene, not a movie (a movie file has a 'scene:' key)"
size="$(sed -n 's/^width: //p' <<<"$info")x$(sed -n 's/^height: //p' <<<"$info")"

start=$(date +%s.%N)
mkdir -p "$outdir"
# The movie appears under its name only if both sides succeeded (pipefail):
# a render that fails half-way leaves no half movie.
tmp="$outdir/.$name.mp4.tmp-$$.mp4"
trap 'rm -f "$tmp"' EXIT
# A trapped signal is acted on only once the pipeline has ended -- stopped
# by the same signal where it reached the whole group (Ctrl-C,
# make_movies.sh) -- so the EXIT trap removes the movie after encode.sh has
# stopped, not while it may still be moving its file into place.
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP
# --clean: the frames of an earlier render of it go first (the folder's other files stay).
"$firsthit" frames "$movie" --out "$outdir/$name" --clean --raw-video - "${frames_options[@]}" \
  | "$here/encode.sh" --raw "$size" "$tmp" --fps "$fps" "${encode_options[@]}" >/dev/null
mv -f "$tmp" "$outdir/$name.mp4"
trap - EXIT
end=$(date +%s.%N)
awk -v a="$start" -v b="$end" -v n="$name" -v o="$outdir/$name.mp4" \
  'BEGIN{printf "%s: rendered and encoded into %s in %.1f s\n", n, o, b-a}'
