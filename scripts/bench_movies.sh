#!/usr/bin/env bash
# The movie pipeline against the encoder alone:
#   1. `make movies` (scripts/make_movies.sh: both movies at once, render,
#      PNG, stream into ffmpeg),
#   2. ffmpeg alone, at its defaults (x264 preset medium on every core),
#      encoding the same 600 frames from the PNG files on disk,
# in alternating rounds -- a shared machine's speed drifts over minutes, and
# a ratio of two runs far apart would measure the drift -- and prints the
# median of each, their ratio, and the peak resident memory of
# `firsthit frames`, as key: value lines.
#
#   scripts/bench_movies.sh [OUTPUT_DIR] [--rounds N]    (default: output/, 3 rounds)
# FIRSTHIT names the binary (default: build/firsthit). Also: make bench-movies.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
outdir=$here/../output rounds=3
while [[ $# -gt 0 ]]; do
  case $1 in
    --rounds) [[ ${2:-} =~ ^[1-9][0-9]*$ ]] || { echo "bench_movies.sh: --rounds needs a number > 0" >&2; exit 2; }
              rounds=$2; shift 2 ;;
    *) outdir=$1; shift ;;
  esac
done
[[ -x /usr/bin/time ]] || { echo "bench_movies.sh: needs GNU time: apt-get install time" >&2; exit 2; }

# Every firsthit run goes through GNU time, which appends its peak RSS (KiB).
rss_log=$(mktemp)
wrapper=$(mktemp)
trap 'rm -f "$rss_log" "$wrapper"' EXIT
printf '#!/bin/sh\nexec /usr/bin/time -a -o %q -f %%M %q "$@"\n' "$rss_log" "$firsthit" >"$wrapper"
chmod +x "$wrapper"

now() { date +%s.%N; }
movies=() alone=()
for ((r = 1; r <= rounds; r++)); do
  t0=$(now)
  FIRSTHIT=$wrapper "$here/make_movies.sh" "$outdir" >&2
  t1=$(now)
  for m in movie1 movie2; do
    "$here/encode.sh" "$outdir/$m" "$outdir/.bench-$m.mp4" --fps 30 >/dev/null
    rm -f "$outdir/.bench-$m.mp4"
  done
  t2=$(now)
  movies+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')")
  alone+=("$(awk -v a="$t1" -v b="$t2" 'BEGIN{print b-a}')")
  echo "bench_movies.sh: round $r of $rounds: make movies ${movies[-1]} s, ffmpeg alone ${alone[-1]} s" >&2
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END{print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
awk -v m="$(median "${movies[@]}")" -v f="$(median "${alone[@]}")" -v n="$rounds" \
    -v rss="$(sort -n "$rss_log" | tail -1)" 'BEGIN{
  printf "rounds: %d\nmovies_seconds: %.1f\nffmpeg_alone_seconds: %.1f\nratio: %.2f\nframes_peak_rss_mb: %.0f\n",
         n, m, f, m/f, rss/1024 }'
