#!/usr/bin/env bash
# `make movies`: the report's Movie 1 and Movie 2, rendered and encoded at the
# same time (scripts/make_movie.sh each), x264 with one thread per movie,
# fed yuv420p frames that firsthit converts on its render threads.
# Two single-threaded encoders beside two renderers keep both cores busy to
# the end with less work in all than one movie at a time with x264 on both
# cores (docs/speed.md). On a terminal one line shows both movies' progress.
#
#   scripts/make_movies.sh [OUTPUT_DIR [MOVIE.yaml ...]]
# (default: output/, and animations/movie1.yaml and movie2.yaml). FIRSTHIT
# names the binary (default: build/firsthit). Exits non-zero if any movie
# failed (the others still finish); Ctrl-C, TERM or HUP stop them all.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
export FIRSTHIT=$firsthit
outdir=${1:-$here/../output}
movies=("$here/../animations/movie1.yaml" "$here/../animations/movie2.yaml")
if [[ $# -ge 2 ]]; then movies=("${@:2}"); fi
names=()
for m in "${movies[@]}"; do names+=("$(basename "$m" .yaml)"); done
if [[ $(printf '%s\n' "${names[@]}" | sort | uniq -d) ]]; then
  echo "make_movies.sh: error: two movies named alike would share $outdir/NAME: ${names[*]}" >&2
  exit 2
fi

# Each movie in a session of its own (setsid), so a signal can stop its whole
# pipeline, renderer and encoder, while this script keeps the terminal and
# gets Ctrl-C itself.
pids=() logs=()
trap 'rm -f "${logs[@]}"' EXIT
show_logs() {
  for i in "${!logs[@]}"; do cat "${logs[$i]}" >&2; done
}
stop() {
  for pid in "${pids[@]}"; do kill -TERM -- "-$pid" 2>/dev/null || true; done
  wait || true
  show_logs
  echo "make_movies.sh: stopped by SIG$1" >&2
  exit "$2"
}
trap 'stop INT 130' INT
trap 'stop TERM 143' TERM
trap 'stop HUP 129' HUP
for m in "${movies[@]}"; do
  logs+=("$(mktemp)")  # what each movie says, shown once the progress line is gone
  setsid "$here/make_movie.sh" "$m" "$outdir" --encoder-threads 1 --raw-pix-fmt yuv420p --quiet >"${logs[-1]}" 2>&1 &
  pids+=($!)
done

if [[ -t 2 ]]; then
  totals=()
  for m in "${movies[@]}"; do totals+=("$("$firsthit" info "$m" 2>/dev/null | sed -n 's/^frames: //p' || true)"); done
  running() { for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && return 0; done; return 1; }
  shopt -s nullglob  # counting frames with a glob: no process started per poll
  while running; do
    line=""
    for i in "${!movies[@]}"; do
      frames=("$outdir/${names[$i]}"/frame_*.png)
      line+="${names[$i]} ${#frames[@]}/${totals[$i]:-?}   "
    done
    printf '\rmake_movies.sh: %s' "$line" >&2
    sleep 1
  done
  printf '\r\033[K' >&2
fi

status=0
for i in "${!pids[@]}"; do
  if wait "${pids[$i]}"; then
    cat "${logs[$i]}"
  else
    status=$?
    cat "${logs[$i]}" >&2  # a failed movie's messages are errors
  fi
done
exit "$status"
