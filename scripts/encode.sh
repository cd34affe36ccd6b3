#!/usr/bin/env bash
# Encodes a movie's frames into a video whose format follows OUT's extension
# (in any case: .mp4 or .MP4):
#   .mp4   H.264 (x264), yuv420p (plays everywhere), +faststart (plays while
#          downloading); odd sides are padded by a pixel
#   .mov   H.264 in QuickTime, the same
#   .webm  VP9 (libvpx-vp9), yuv420p, constant quality (-crf 32 -b:v 0)
#   .gif   a GIF with its own 256-colour palette (palettegen + paletteuse)
# Any other extension, or none, is refused before anything runs. The video
# is written under a temporary name in OUT's folder and renamed, so it is
# whole or absent.
#
#   scripts/encode.sh FRAMES OUT [--movie MOVIE.yaml] [--fps F] [--threads N]
#       FRAMES is what `firsthit frames --out` was given: a folder of
#       frame_0000.png, frame_0001.png, ..., or a pattern such as
#       'shots/take1_%04d.png' or 'shots/take1_####.png'. The frames must be
#       0 to n-1, all with the same zero padding (a gap is refused).
#   scripts/encode.sh --raw WIDTHxHEIGHT OUT [--movie MOVIE.yaml] [--fps F] [--threads N] [--pix-fmt P]
#       raw frames on standard input, as `firsthit frames --raw-video -`
#       writes them while it renders: the encoder then runs beside the
#       renderer (scripts/make_movie.sh). RGB24 (the default) gives the same
#       video as encoding the frame files afterwards; yuv420p frames
#       (`--raw-pix-fmt yuv420p`) skip ffmpeg's own colour conversion.
#
# The fps, the first of:
#   --fps F              given explicitly: it always wins
#   --movie MOVIE.yaml   the movie's fps, from `firsthit info MOVIE` (FIRSTHIT
#                        names the binary; default: build/firsthit)
#   PREFIXmovie.txt      the movie's `key: value` lines that `firsthit frames`
#                        writes beside its frames (frame_movie.txt beside
#                        frame_NNNN.png, take1_movie.txt beside take1_NNNN.png;
#                        at least `fps: F` and `frames: N`); not read when
#                        --movie is given
#   30, with a warning on standard error.
# When the movie's frame count is known (from --movie, or else PREFIXmovie.txt), a
# folder must hold exactly its frames: frames past the movie's end (left by
# an earlier, longer render) are refused, and so are missing last frames
# (render them with `firsthit frames MOVIE --resume`). Refused means exit 2,
# one line on standard error, nothing written. (Raw frames on standard input
# are not counted.) Options may stand before or after the paths.
#
#   --threads N: the encoder's threads (default: ffmpeg's choice, all cores).
#       The video depends on it: encode with the same N to get the same bytes.
#       `make movies` uses 1 per movie, with both movies at once: less work
#       in all than x264 sharing two cores with itself.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)

die() { echo "encode.sh: error: $*" >&2; exit 2; }
usage="usage: scripts/encode.sh FRAMES_DIR|PATTERN OUT.(mp4|webm|gif|mov) [--movie MOVIE.yaml] [--fps F] [--threads N]  |  scripts/encode.sh --raw WxH OUT.(mp4|webm|gif|mov) [--movie MOVIE.yaml] [--fps F] [--threads N] [--pix-fmt rgb24|yuv420p]"
supported=".mp4 (H.264), .webm (VP9), .gif, .mov (H.264)"
# A number > 0, as ffmpeg's -framerate takes it (30, 29.97).
is_fps() { [[ $1 =~ ^[0-9]+([.][0-9]+)?$ ]] && awk "BEGIN{exit !($1 > 0)}"; }
# The value of a `key: value` line on standard input (the first), trimmed.
value_of() {
  awk -v k="$1" 'index($0, k ":") == 1 { v = substr($0, length(k) + 2); gsub(/^[ \t]+|[ \t\r]+$/, "", v); print v; exit }'
}

raw_size='' fps='' movie='' raw_pix_fmt=''
threads=() positional=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --raw)
      [[ $# -ge 2 ]] || die "--raw needs WIDTHxHEIGHT"
      [[ $2 =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || die "--raw needs WIDTHxHEIGHT (e.g. 800x800), got '$2'"
      raw_size=$2; shift 2 ;;
    --fps) [[ $# -ge 2 ]] || die "--fps needs a value"; fps=$2; shift 2 ;;
    --movie) [[ $# -ge 2 && -n $2 ]] || die "--movie needs a movie file (MOVIE.yaml)"; movie=$2; shift 2 ;;
    --threads)
      [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || die "--threads needs a whole number > 0, got '${2:-}'"
      threads=(-threads "$2"); shift 2 ;;
    --pix-fmt)
      [[ ${2:-} == rgb24 || ${2:-} == yuv420p ]] || die "--pix-fmt is rgb24 or yuv420p, got '${2:-}'"
      raw_pix_fmt=$2; shift 2 ;;
    -h | --help) echo "$usage"; exit 0 ;;
    -?*) die "unknown option '$1'" ;;
    *) positional+=("$1"); shift ;;
  esac
done
if [[ -n $raw_size ]]; then
  [[ ${#positional[@]} -eq 1 ]] || die "$usage"
  dir='' out=${positional[0]}
else
  [[ ${#positional[@]} -eq 2 ]] || die "$usage"
  frames_arg=${positional[0]} out=${positional[1]}
  [[ -z $raw_pix_fmt ]] || die "--pix-fmt is for --raw frames (frame files are PNG)"
  # A folder of frame_NNNN.png, or a pattern: PREFIX %0Nd|%d|#### SUFFIX.
  dir=$frames_arg prefix=frame_ suffix=.png
  base=${frames_arg##*/}
  # (The first number in the name: a greedy prefix once took '###' of
  # '####' for itself. An existing folder is a folder, '#' in its name or not.)
  if [[ ! -d $frames_arg && $base =~ ^([^%#]*)(%0?[0-9]*d|#+)(.*)$ ]]; then
    prefix=${BASH_REMATCH[1]} suffix=${BASH_REMATCH[3]}
    [[ $prefix != *[%#]* && $suffix != *[%#]* ]] || die "$frames_arg has two frame numbers; give one (%04d or ####)"
    [[ $frames_arg == */* ]] && dir=${frames_arg%/*} || dir=.
    [[ -n $dir ]] || dir=/
  fi
  sidecar_file=$dir/${prefix}movie.txt
fi
raw_pix_fmt=${raw_pix_fmt:-rgb24}

# The format, from the extension, before anything else runs.
name=$(basename -- "$out")
ext=
[[ $name == *.* ]] && ext=${name##*.}
ext=${ext,,}
case $ext in
  mp4) label="MP4, H.264" ;;
  mov) label="QuickTime, H.264" ;;
  webm) label="WebM, VP9" ;;
  gif) label="GIF" ;;
  *) die "cannot write '$out': the output's extension picks the format; supported: $supported" ;;
esac
outdir=$(dirname -- "$out")
[[ -d $outdir ]] || die "cannot write '$out': folder '$outdir' does not exist"
[[ ! -d $out ]] || die "cannot write '$out': it is a folder"
[[ -z $fps ]] || is_fps "$fps" || die "--fps must be a number > 0, got '$fps'"
command -v ffmpeg >/dev/null || die "ffmpeg not found; install it with: apt-get install ffmpeg"

# The movie's fps and frame count: from --movie, or else the frames' PREFIXmovie.txt.
movie_fps='' count='' count_from=''
if [[ -n $movie ]]; then
  firsthit=${FIRSTHIT:-$here/../build/firsthit}
  command -v "$firsthit" >/dev/null || die "--movie needs firsthit, not found at $firsthit (build it, or set FIRSTHIT)"
  info=$("$firsthit" info "$movie") || exit 2  # firsthit said why, in one line
  movie_fps=$(value_of fps <<<"$info") count=$(value_of frames <<<"$info") count_from=$movie
  [[ -n $movie_fps ]] || die "--movie $movie: not a movie file (a scene has no fps)"
elif [[ -z $raw_size && -f $sidecar_file ]]; then
  sidecar=$(<"$sidecar_file")
  movie_fps=$(value_of fps <<<"$sidecar") count=$(value_of frames <<<"$sidecar") count_from=$sidecar_file
fi
if [[ -n $count_from ]]; then
  is_fps "$movie_fps" || die "$count_from: expected a line 'fps: F' with F a number > 0, got '$movie_fps'"
  [[ $count =~ ^[1-9][0-9]*$ ]] || die "$count_from: expected a line 'frames: N' with N a whole number > 0, got '$count'"
fi
fps_warning=
if [[ -z $fps ]]; then
  fps=${movie_fps:-30}
  [[ -n $movie_fps ]] || fps_warning="no fps given${dir:+ and there is no $sidecar_file}: encoding at 30 fps; pass --movie MOVIE.yaml (the movie's fps) or --fps F"
fi

if [[ -n $raw_size ]]; then
  input=(-f rawvideo -pix_fmt "$raw_pix_fmt" -s "$raw_size" -framerate "$fps" -i -)
  what="raw frames from standard input"
  width=${raw_size%x*} height=${raw_size#*x}
else
  [[ -d $dir ]] || die "no such folder: $dir"
  # The frame files by number: PREFIX DIGITS SUFFIX.
  declare -A by_index=()
  n=0 digits='' extra='' extra_index=''
  for path in "$dir/$prefix"*"$suffix"; do
    [[ -f $path ]] || continue
    f=${path##*/} number=${f#"$prefix"}
    number=${number%"$suffix"}
    [[ $number =~ ^[0-9]+$ && ${#number} -le 9 ]] || continue
    i=$((10#$number))
    by_index[$i]=$f
    n=$((n + 1))
    # No frame past the movie's end: stale frames of an earlier, longer
    # render would play on after it.
    if [[ -n $count ]] && ((i >= count)) && [[ -z $extra || $i -lt $extra_index ]]; then extra=$f extra_index=$i; fi
  done
  [[ $n -gt 0 ]] || die "$frames_arg holds no frames (${prefix}0000${suffix}, ...)"
  [[ -z $extra ]] || die "$frames_arg holds frames past the movie's end ($count frames, from $count_from): $extra is the first; remove them, or render into a fresh folder (firsthit frames --clean)"
  [[ -n ${by_index[0]:-} ]] || die "$frames_arg has no frame 0 (${prefix}0000${suffix})"
  first=${by_index[0]}
  digits=$(( ${#first} - ${#prefix} - ${#suffix} ))
  name_of() { printf "%s%0${digits}d%s" "$prefix" "$1" "$suffix"; }
  # The frames must be 0..n-1, all with the same zero padding.
  mapfile -t sorted < <(printf '%s\n' "${!by_index[@]}" | sort -n)
  for ((i = 0; i < n; i++)); do
    want=$(name_of "$i") found=${by_index[${sorted[i]}]}
    [[ $found == "$want" ]] || die "$frames_arg has a gap or stray frame: expected $want, found $found (render the missing frames with 'firsthit frames MOVIE --resume')"
  done
  if [[ -n $count ]] && ((n < count)); then
    missing="$(name_of "$n") is"
    ((n == count - 1)) || missing="$(name_of "$n") to $(name_of $((count - 1))) are"
    die "$frames_arg holds $n of the movie's $count frames (from $count_from): $missing missing (render the missing frames with 'firsthit frames MOVIE --resume')"
  fi
  frames=("$first")
  # ffmpeg reads the frames by its own pattern: a '%' in the name is '%%'.
  input=(-framerate "$fps" -i "${dir//%/%%}/${prefix//%/%%}%0${digits}d${suffix//%/%%}")
  what="$n frame$( ((n == 1)) || echo s)"
  # The size, from the first frame's IHDR chunk (bytes 16-23, big-endian).
  read -r width height < <(od -An -tu1 -j16 -N8 "$dir/${frames[0]}" |
    awk '{print ($1*16777216 + $2*65536 + $3*256 + $4), ($5*16777216 + $6*65536 + $7*256 + $8)}') || true
  [[ ${width:-0} -gt 0 && ${height:-0} -gt 0 ]] || die "$dir/${frames[0]} is not a PNG file"
  # Every frame a PNG of the first one's size: ffmpeg would scale another
  # size to fit without a word (and -xerror below stops at a frame whose
  # data is broken).
  for ((i = 1; i < n; i++)); do
    f=$(name_of "$i")
    read -r sig w h < <(od -An -tu1 -N24 "$dir/$f" | tr -s ' \n' ' ' |
      awk '{print $1 "-" $2 "-" $3 "-" $4, ($17*16777216 + $18*65536 + $19*256 + $20), ($21*16777216 + $22*65536 + $23*256 + $24)}') || true
    [[ ${sig:-} == 137-80-78-71 ]] || die "$dir/$f is not a PNG file"
    [[ $w == "$width" && $h == "$height" ]] || die "$dir/$f is ${w}x${h}, the frames before it ${width}x${height}"
  done
fi

filter=() codec=()
case $ext in
  mp4 | mov)
    # H.264 in yuv420p needs even sides: pad odd ones by a pixel. (Only then:
    # the filter costs a copy of every frame.)
    (( width % 2 == 0 && height % 2 == 0 )) || filter=(-vf "pad=ceil(iw/2)*2:ceil(ih/2)*2")
    codec=(-c:v libx264 -preset medium "${threads[@]}" -pix_fmt yuv420p -movflags +faststart) ;;
  webm)
    # Constant quality (-b:v 0: no bitrate cap); VP9 takes odd sides as they
    # are. bitexact: no random segment UID, so the same frames give the same
    # bytes.
    codec=(-c:v libvpx-vp9 -crf 32 -b:v 0 -row-mt 1 "${threads[@]}" -pix_fmt yuv420p -fflags +bitexact) ;;
  gif)
    # One palette for the whole movie, made from its own frames.
    filter=(-vf "split[a][b];[a]palettegen[p];[b][p]paletteuse")
    codec=("${threads[@]}") ;;
esac

[[ -z $fps_warning ]] || echo "encode.sh: warning: $fps_warning" >&2
# The muxer is named (-f): the temporary's extension does not pick it.
tmp="$outdir/.$name.tmp-$$.$ext"
# ffmpeg runs in the background and is waited for, so that a signal to this
# script stops it too, and the file goes only once ffmpeg has stopped: a
# stopping ffmpeg still finishes its output, and may even create it, after
# an earlier rm (make_movies.sh's SIGTERM test once found one left behind).
encoder=""
stop() {
  if [[ -n $encoder ]]; then
    kill -TERM "$encoder" 2>/dev/null || true
    wait "$encoder" 2>/dev/null || true
  fi
  exit "$1"
}
trap 'stop 130' INT
trap 'stop 143' TERM
trap 'stop 129' HUP
# -xerror: a frame ffmpeg cannot decode stops it (it used to be skipped, the
# movie one frame short, and the run a success). Its messages are kept for
# the one line said of a failure.
log="$outdir/.$name.log-$$"
trap 'rm -f "$tmp" "$log"' EXIT
ffmpeg -hide_banner -loglevel error -nostdin -y -xerror "${input[@]}" \
  "${filter[@]}" "${codec[@]}" -f "$ext" "$tmp" <&0 2>"$log" &
encoder=$!
status=0
wait "$encoder" || status=$?
trap - INT TERM HUP
if ((status != 0)); then
  echo "encode.sh: error: ffmpeg stopped (exit $status) encoding $what: $(grep -m1 . "$log" || echo 'no message')" >&2
  exit 1
fi
# (ffmpeg may end well having written nothing: no frames on standard input.)
frames_out=$(ffprobe -v error -count_packets -select_streams v:0 -show_entries stream=nb_read_packets \
  -of csv=p=0 -f "$ext" "$tmp" 2>/dev/null || true)
[[ -s $tmp && ${frames_out:-0} -gt 0 ]] || { echo "encode.sh: error: ffmpeg wrote no frame into $out: no frames?" >&2; exit 1; }
mv -f "$tmp" "$out"
rm -f "$log"
trap - EXIT
echo "encoded $what at $fps fps into $out ($label)"
