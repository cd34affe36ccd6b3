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
while [[ $# -gt 0 ]]; do
  case $1 in
    --encoder-threads) [[ $# -ge 2 ]] || { echo "$usage" >&2; exit 2; }; encode_options+=(--threads "$2"); shift 2 ;;
    --raw-pix-fmt) [[ $# -ge 2 ]] || { echo "$usage" >&2; exit 2; }
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
# A trapped signal is acted on only once the pipeline has ended -- stopped
# by the same signal where it reached the whole group (Ctrl-C,
# make_movies.sh) -- so the EXIT trap removes the movie after encode.sh has
# stopped, not while it may still be moving its file into place.
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP
"$firsthit" frames "$movie" --out "$outdir/$name" --raw-video - "${frames_options[@]}" \
  | "$here/encode.sh" --raw "$size" "$tmp" --fps "$fps" "${encode_options[@]}" >/dev/null
mv -f "$tmp" "$outdir/$name.mp4"
trap - EXIT
end=$(date +%s.%N)
awk -v a="$start" -v b="$end" -v n="$name" -v o="$outdir/$name.mp4" \
  'BEGIN{printf "%s: rendered and encoded into %s in %.1f s\n", n, o, b-a}'
