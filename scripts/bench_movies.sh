#!/usr/bin/env bash
# The movie pipeline against the encoder alone (issue 7, target 3):
#   1. `make movies` (scripts/make_movies.sh: both movies at once, render,
#      PNG, stream into ffmpeg),
#   2. ffmpeg alone, at its defaults (x264 preset medium on every core),
#      encoding the same 600 frames from the PNG files on disk,
# and prints both times, their ratio and the peak resident memory of
# `firsthit frames`, as key: value lines.
#
#   scripts/bench_movies.sh [OUTPUT_DIR]      (default: output/)
# FIRSTHIT names the binary (default: build/firsthit). Also: make bench-movies.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
outdir=${1:-$here/../output}
[[ -x /usr/bin/time ]] || { echo "bench_movies.sh: needs GNU time: apt-get install time" >&2; exit 2; }

# Every firsthit run goes through GNU time, which appends its peak RSS (KiB).
rss_log=$(mktemp)
wrapper=$(mktemp)
trap 'rm -f "$rss_log" "$wrapper"' EXIT
printf '#!/bin/sh\nexec /usr/bin/time -a -o %q -f %%M %q "$@"\n' "$rss_log" "$firsthit" >"$wrapper"
chmod +x "$wrapper"

now() { date +%s.%N; }
t0=$(now)
FIRSTHIT=$wrapper "$here/make_movies.sh" "$outdir" >&2
t1=$(now)
for m in movie1 movie2; do
  "$here/encode.sh" "$outdir/$m" "$outdir/.bench-$m.mp4" >&2
  rm -f "$outdir/.bench-$m.mp4"
done
t2=$(now)
awk -v a="$t0" -v b="$t1" -v c="$t2" -v rss="$(sort -n "$rss_log" | tail -1)" 'BEGIN{
  printf "movies_seconds: %.1f\nffmpeg_alone_seconds: %.1f\nratio: %.2f\nframes_peak_rss_mb: %.0f\n",
         b-a, c-b, (b-a)/(c-b), rss/1024 }'
