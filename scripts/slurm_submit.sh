#!/usr/bin/env bash
# Renders a movie on a Slurm cluster: submits
#   1. a job array of TASKS tasks; task k renders its shard of the frames
#      (firsthit frames --shard auto: the frames i with i mod TASKS == k) with
#      --resume and the CPUs Slurm gave it, and
#   2. an encode job that runs scripts/encode.sh only after every task
#      succeeded (--dependency=afterok), at the movie's fps.
# Then prints the two job ids ("render_job: ID", "encode_job: ID") and returns.
#
#   scripts/slurm_submit.sh MOVIE OUT_DIR TASKS [extra sbatch args ...]
#
# The frames go to OUT_DIR/frame_NNNN.png, the movie to OUT_DIR.mp4, the
# jobs' logs to OUT_DIR.logs/. MOVIE, its scene, OUT_DIR and the firsthit
# binary (env FIRSTHIT, default build/firsthit next to this script) must be
# on storage every node sees, at the same paths; ffmpeg must be on the node
# that encodes. The default build (bash scripts/setup.sh) runs on every
# x86-64 node at that node's widest SIMD, whatever the mix. Extra arguments go to
# both sbatch calls (e.g. --partition=render --cpus-per-task=8 --time=1:00:00).
#
# Every task is idempotent: a task that is requeued (node failure, preemption,
# scontrol requeue) or run again renders only its missing frames. After a
# failed task (the encode job is then cancelled), fix the cause and run the
# same command again: tasks whose frames are all there end at once.
set -euo pipefail

die() { echo "slurm_submit.sh: error: $*" >&2; exit 2; }

here=$(cd "$(dirname "$0")" && pwd)
[[ $# -ge 3 ]] || die "usage: scripts/slurm_submit.sh MOVIE OUT_DIR TASKS [extra sbatch args ...]"
movie=$1 out=$2 tasks=$3
shift 3
[[ $tasks =~ ^[1-9][0-9]{0,6}$ ]] || die "TASKS must be a whole number >= 1, got '$tasks'"
for a in "$@"; do
  case $a in
    -a | --array | --array=* | -d | --dependency | --dependency=*)
      die "'$a': the job array and the dependency are this script's to set" ;;
  esac
done
[[ -f $movie ]] || die "no such movie file: $movie"
firsthit=${FIRSTHIT:-$here/../build/firsthit}
[[ -x $firsthit ]] || die "firsthit not found at $firsthit (build it: cmake --build build; or set FIRSTHIT)"
command -v sbatch >/dev/null || die "sbatch not found: run this on a Slurm submit host"

# The jobs run on other machines and in other folders: absolute paths only.
movie=$(realpath "$movie")
out=$(realpath -m "$out")
firsthit=$(realpath "$firsthit")
logs=$out.logs

# firsthit checks the movie here, before anything is queued, and tells the fps.
info=$("$firsthit" info "$movie") || exit $?
grep -qx 'kind: movie' <<<"$info" || die "$movie is a scene file, not a movie file (a movie file has a 'scene:' key)"
fps=$(awk '$1 == "fps:" {print $2}' <<<"$info")
frames=$(awk '$1 == "frames:" {print $2}' <<<"$info")
[[ -n $fps && -n $frames ]] || die "'firsthit info $movie' printed no fps or frames"
((tasks <= frames)) || echo "slurm_submit.sh: warning: $tasks tasks for $frames frames: $((tasks - frames)) task(s) will have nothing to render" >&2

mkdir -p "$out" "$logs"

# --requeue: Slurm may requeue a task (node failure, preemption); the rerun
# appends to the task's log (--open-mode=append) and resumes.
render_job=$(sbatch --parsable --job-name=firsthit-render --array="0-$((tasks - 1))" --requeue \
  --open-mode=append --output="$logs/render-%A_%a.out" "$@" \
  "$here/slurm/render.sbatch" "$firsthit" "$movie" "$out")
render_job=${render_job%%;*}  # --parsable prints ID or ID;CLUSTER

# --kill-on-invalid-dep: if a task fails, the encode job is cancelled rather
# than left pending forever (DependencyNeverSatisfied).
if ! encode_job=$(sbatch --parsable --job-name=firsthit-encode --dependency="afterok:$render_job" \
  --kill-on-invalid-dep=yes --output="$logs/encode-%j.out" "$@" \
  "$here/slurm/encode.sbatch" "$here/encode.sh" "$out" "$out.mp4" "$fps"); then
  scancel "$render_job" || true
  die "submitting the encode job failed; cancelled the render job array $render_job"
fi
encode_job=${encode_job%%;*}

echo "render_job: $render_job"
echo "encode_job: $encode_job"
echo "slurm_submit.sh: $tasks tasks render $frames frames into $out; then $out.mp4; logs in $logs" >&2
