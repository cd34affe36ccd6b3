#!/usr/bin/env bash
# A contact sheet of a movie's frames: every Nth frame, scaled down, tiled in
# a grid (ffmpeg's select, scale and tile filters), so one image shows the orbit.
#
#   scripts/contact_sheet.sh FRAMES_DIR OUT.png [--every N] [--cols C] [--size PX]
# defaults: every 25th frame, 4 columns, 200 px tiles.
set -euo pipefail
die() { echo "contact_sheet.sh: error: $*" >&2; exit 2; }
[[ $# -ge 2 ]] || die "usage: scripts/contact_sheet.sh FRAMES_DIR OUT.png [--every N] [--cols C] [--size PX]"
dir=$1 out=$2 every=25 cols=4 size=200
shift 2
while [[ $# -gt 0 ]]; do
  case $1 in
    --every) every=$2; shift 2 ;;
    --cols) cols=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    *) die "unknown option '$1'" ;;
  esac
done
command -v ffmpeg >/dev/null || die "ffmpeg not found; install it with: apt-get install ffmpeg"
n=$(ls -1 "$dir" 2>/dev/null | grep -cE '^frame_[0-9]+\.png$' || true)
[[ $n -gt 0 ]] || die "$dir holds no frames"
first=$(ls -1 "$dir" | grep -E '^frame_[0-9]+\.png$' | sort | head -1)
digits=$(( ${#first} - 10 ))
tiles=$(( (n + every - 1) / every ))
rows=$(( (tiles + cols - 1) / cols ))
ffmpeg -hide_banner -loglevel error -y -i "$dir/frame_%0${digits}d.png" \
  -vf "drawtext=text='frame %{n}':x=8:y=8:fontsize=36:fontcolor=white:box=1:boxcolor=black@0.5,select='not(mod(n\,$every))',scale=$size:-1,tile=${cols}x${rows}:padding=4:color=white" \
  -frames:v 1 -update 1 "$out" 2>/dev/null || \
ffmpeg -hide_banner -loglevel error -y -i "$dir/frame_%0${digits}d.png" \
  -vf "select='not(mod(n\,$every))',scale=$size:-1,tile=${cols}x${rows}:padding=4:color=white" \
  -frames:v 1 -update 1 "$out"
echo "contact sheet of $tiles frames (every $every) in $out"
