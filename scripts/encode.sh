#!/usr/bin/env bash
# Encodes frames into an MP4: H.264, yuv420p (plays everywhere), the movie's
# fps, +faststart (plays while downloading). The MP4 is written under a
# temporary name and renamed, so it is whole or absent.
#
#   scripts/encode.sh FRAMES_DIR OUT.mp4 [--fps N] [--threads N]
#       a folder of frame_0000.png, frame_0001.png, ... (default fps: 30)
#   scripts/encode.sh --raw WIDTHxHEIGHT OUT.mp4 [--fps N] [--threads N] [--pix-fmt P]
#       raw frames on standard input, as `firsthit frames --raw-video -`
#       writes them while it renders: the encoder then runs beside the
#       renderer (scripts/make_movie.sh). RGB24 (the default) gives the same
#       video as encoding the frame files afterwards; yuv420p frames
#       (`--raw-pix-fmt yuv420p`) skip ffmpeg's own colour conversion.
#   --threads N: x264's threads (default: ffmpeg's choice, all cores). The
#       video depends on it: encode with the same N to get the same bytes.
#       `make movies` uses 1 per movie, with both movies at once: less work
#       in all than x264 sharing two cores with itself.
set -euo pipefail

die() { echo "encode.sh: error: $*" >&2; exit 2; }
usage="usage: scripts/encode.sh FRAMES_DIR OUT.mp4 [--fps N] [--threads N]  |  scripts/encode.sh --raw WxH OUT.mp4 [--fps N] [--threads N] [--pix-fmt rgb24|yuv420p]"

raw_size=
if [[ ${1:-} == --raw ]]; then
  [[ $# -ge 2 ]] || die "--raw needs WIDTHxHEIGHT"
  raw_size=$2
  shift 2
  [[ $raw_size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || die "--raw needs WIDTHxHEIGHT (e.g. 800x800), got '$raw_size'"
  [[ $# -ge 1 ]] || die "$usage"
  dir= out=$1
  shift 1
else
  [[ $# -ge 2 ]] || die "$usage"
  dir=$1 out=$2
  shift 2
fi
fps=30
threads=()
raw_pix_fmt=rgb24
while [[ $# -gt 0 ]]; do
  case $1 in
    --fps) [[ $# -ge 2 ]] || die "--fps needs a value"; fps=$2; shift 2 ;;
    --threads)
      [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || die "--threads needs a whole number > 0, got '${2:-}'"
      threads=(-threads "$2"); shift 2 ;;
    --pix-fmt)
      [[ -n $raw_size ]] || die "--pix-fmt is for --raw frames (frame files are PNG)"
      [[ ${2:-} == rgb24 || ${2:-} == yuv420p ]] || die "--pix-fmt is rgb24 or yuv420p, got '${2:-}'"
      raw_pix_fmt=$2; shift 2 ;;
    *) die "unknown option '$1'" ;;
  esac
done
[[ $fps =~ ^[0-9]+([.][0-9]+)?$ ]] && awk "BEGIN{exit !($fps > 0)}" || die "--fps must be a number > 0, got '$fps'"
command -v ffmpeg >/dev/null || die "ffmpeg not found; install it with: apt-get install ffmpeg"

if [[ -n $raw_size ]]; then
  input=(-f rawvideo -pix_fmt "$raw_pix_fmt" -s "$raw_size" -framerate "$fps" -i -)
  what="raw frames from standard input"
  width=${raw_size%x*} height=${raw_size#*x}
else
  [[ -d $dir ]] || die "no such folder: $dir"
  # The frames must be frame_0..frame_{n-1}, all with the same zero padding.
  mapfile -t frames < <(cd "$dir" && ls -1 | grep -E '^frame_[0-9]+\.png$' | sort)
  n=${#frames[@]}
  [[ $n -gt 0 ]] || die "$dir holds no frames (frame_0000.png, ...)"
  digits=$(( ${#frames[0]} - 10 ))  # "frame_" + digits + ".png"
  for ((i = 0; i < n; i++)); do
    want=$(printf "frame_%0${digits}d.png" "$i")
    [[ ${frames[$i]} == "$want" ]] || die "$dir has a gap or stray frame: expected $want, found ${frames[$i]} (render the missing frames with 'firsthit frames MOVIE --resume')"
  done
  input=(-framerate "$fps" -i "$dir/frame_%0${digits}d.png")
  what="$n frames"
  # The size, from the first frame's IHDR chunk (bytes 16-23, big-endian).
  read -r width height < <(od -An -tu1 -j16 -N8 "$dir/${frames[0]}" |
    awk '{print ($1*16777216 + $2*65536 + $3*256 + $4), ($5*16777216 + $6*65536 + $7*256 + $8)}') || true
  [[ ${width:-0} -gt 0 && ${height:-0} -gt 0 ]] || die "$dir/${frames[0]} is not a PNG file"
fi
# H.264 in yuv420p needs even sides: pad odd ones by a pixel. (Only then: the
# filter costs a copy of every frame.)
pad=()
(( width % 2 == 0 && height % 2 == 0 )) || pad=(-vf "pad=ceil(iw/2)*2:ceil(ih/2)*2")

tmp="$(dirname "$out")/.$(basename "$out").tmp-$$.mp4"
trap 'rm -f "$tmp"' EXIT
ffmpeg -hide_banner -loglevel error -nostdin -y "${input[@]}" \
  "${pad[@]}" -c:v libx264 -preset medium "${threads[@]}" -pix_fmt yuv420p \
  -movflags +faststart "$tmp"
mv -f "$tmp" "$out"
trap - EXIT
echo "encoded $what at $fps fps into $out"
