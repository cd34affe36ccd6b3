#!/usr/bin/env bash
# slurm.job_array: a real one-node Slurm cluster on this machine.
#
# Starts munged, slurmctld and slurmd, each configured in a temporary folder
# (own MUNGE key and socket, free local ports, state, spool and logs there),
# submits a 64x64, 24-frame movie with scripts/slurm_submit.sh as 4 array
# tasks plus the encode job, and checks: every task completed, the MP4
# (ffprobe: h264, 64x64, 24 frames), every frame byte for byte against a
# single-machine `firsthit frames` run. Then deletes two frames of task 1's
# shard, requeues that task (scontrol requeue) and checks it rendered exactly
# those two again. Last, a submission whose task 2 fails: the encode job is
# cancelled, no MP4; the same command run again renders only task 2's
# missing frames and encodes. Every daemon is stopped at the end, whatever
# happens.
#
#   bash tests/slurm/test_slurm.sh FIRSTHIT SOURCE_DIR
#
# Exit: 0 pass, 1 fail, 77 skipped (CTest SKIP_RETURN_CODE): only when not
# run as root, which slurmd needs to launch jobs. Missing packages are a
# failure, not a skip: scripts/setup.sh installs them.
# KEEP_SLURM_TEST=1 keeps the temporary folder (its path is printed).
set -euo pipefail

[[ $# -eq 2 ]] || { echo "usage: test_slurm.sh FIRSTHIT SOURCE_DIR" >&2; exit 2; }
firsthit=$(realpath "$1")
src=$(realpath "$2")
start_time=$SECONDS

log() { echo "[$((SECONDS - start_time))s] $*"; }
fail() {
  echo "FAIL: $*" >&2
  dump_logs
  exit 1
}

# Nothing from a surrounding Slurm job or user defaults may leak in.
while read -r v; do unset "$v"; done < <(env | grep -oE '^(SLURM|SBATCH|SQUEUE|SINFO|SCONTROL)_[A-Za-z0-9_]*' || true)

if [[ $(id -u) -ne 0 ]]; then
  echo "SKIP: the one-node Slurm cluster needs root (slurmd launches each job as its user); run as root"
  exit 77
fi
for tool in munged munge slurmctld slurmd sbatch squeue scontrol scancel sinfo ffprobe ffmpeg timeout; do
  command -v "$tool" >/dev/null || fail "'$tool' not found: install the packages with scripts/setup.sh (slurm-wlm, munge, ffmpeg)"
done

# munged wants its socket's folder and every folder above it searchable by all.
tmp=$(mktemp -d /tmp/firsthit_slurm.XXXXXX)
chmod 755 "$tmp"
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool" "$tmp/log" "$tmp/movie"
pids=()
array_job="" encode_job=""

dump_logs() {
  [[ -n ${tmp:-} ]] || return 0
  for f in "$tmp"/log/* "$tmp"/out/*.logs/*; do
    [[ -f $f ]] || continue
    echo "----- $f (last 30 lines)" >&2
    tail -n 30 "$f" >&2
  done
}

cleanup() {
  local status=$?
  trap - EXIT INT TERM
  # Jobs first (their slurmstepd outlive slurmd), then the daemons.
  if [[ -n ${SLURM_CONF:-} ]] && [[ ${#pids[@]} -ge 3 ]]; then
    scancel --quiet ${array_job:+"$array_job"} ${encode_job:+"$encode_job"} 2>/dev/null || true
    for _ in $(seq 50); do
      [[ -z $(squeue -h -o %i 2>/dev/null) ]] && break
      sleep 0.2
    done
  fi
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill "${pids[i]}" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [[ ${KEEP_SLURM_TEST:-0} == 1 ]]; then echo "kept $tmp"; else rm -rf "$tmp"; fi
  log "daemons stopped"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# A daemon in the background, started under `timeout`: should this script be
# killed outright (no trap), the daemons still end within 5 minutes.
daemon() {
  local name=$1
  shift
  timeout --kill-after=5 300 "$@" >"$tmp/log/$name.out" 2>&1 &
  pids+=($!)
}

# A local TCP port nobody listens on (checked against /proc/net/tcp*).
free_port() {
  local port hex
  while true; do
    port=$((20000 + RANDOM % 40000))
    hex=$(printf ':%04X ' "$port")
    grep -q -- "$hex" /proc/net/tcp /proc/net/tcp6 2>/dev/null || { echo "$port"; return; }
  done
}

# wait_until SECONDS WHAT COMMAND...: polls COMMAND every 0.5 s.
wait_until() {
  local limit=$1 what=$2
  shift 2
  local end=$((SECONDS + limit))
  until "$@"; do
    ((SECONDS < end)) || fail "timed out after ${limit}s waiting for $what"
    sleep 0.5
  done
}

# --- the submit script's own usage errors, before any cluster -------------
usage_err=$(FIRSTHIT=$firsthit bash "$src/scripts/slurm_submit.sh" "$src/animations/movie1.yaml" "$tmp/x" 0 2>&1) && fail "TASKS 0 accepted"
[[ $usage_err == "slurm_submit.sh: error: TASKS must be a whole number >= 1, got '0'" ]] || fail "TASKS 0: $usage_err"
FIRSTHIT=$firsthit bash "$src/scripts/slurm_submit.sh" "$src/animations/scene.yaml" "$tmp/x" 2 >/dev/null 2>&1 && fail "a scene file accepted as MOVIE"

# --- MUNGE: own key, socket, pid, seed and log ------------------------------
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
socket=$tmp/munge/munge.socket
daemon munged munged --foreground --force --socket="$socket" --key-file="$tmp/munge/munge.key" \
  --log-file="$tmp/log/munged.log" --pid-file="$tmp/munge/munged.pid" --seed-file="$tmp/munge/munged.seed"
munge_ok() { munge -S "$socket" -n 2>/dev/null | unmunge -S "$socket" >/dev/null 2>&1; }
wait_until 15 "munged to answer on $socket" munge_ok
log "munged up"

# --- Slurm: one node, this host, 2 CPUs -----------------------------------
node=$(hostname -s)
ctld_port=$(free_port)
slurmd_port=$(free_port)
while [[ $slurmd_port == "$ctld_port" ]]; do slurmd_port=$(free_port); done
export SLURM_CONF=$tmp/slurm.conf
cat >"$SLURM_CONF" <<EOF
# A throwaway one-node cluster for firsthit's tests/slurm/test_slurm.sh.
ClusterName=firsthit-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
# cred_expire: a requeued job may start again after this many seconds (default 120).
AuthInfo=socket=$socket,cred_expire=10
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MailProg=/bin/true
# No cgroups: track job processes through /proc, no task binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=2
ReturnToService=2
MinJobAge=600
# The node as configured, whatever this machine's CPU count.
SlurmdParameters=config_overrides
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
daemon slurmctld slurmctld -D -f "$SLURM_CONF"
daemon slurmd slurmd -D -f "$SLURM_CONF" -N "$node"
node_idle() {
  local dead
  for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null || dead=1; done
  [[ -z ${dead:-} ]] || fail "a daemon died while starting"
  [[ $(sinfo -h -n "$node" -o %T 2>/dev/null) == idle ]]
}
wait_until 60 "node $node to be idle (slurmctld port $ctld_port, slurmd port $slurmd_port)" node_idle
log "slurmctld and slurmd up, node $node idle"

# --- a small movie and its single-machine reference ------------------------
sed -e 's/width: 800/width: 64/' -e 's/height: 800/height: 64/' "$src/animations/scene.yaml" >"$tmp/movie/scene.yaml"
cat >"$tmp/movie/tiny.yaml" <<'EOF'
scene: scene.yaml
camera: perspective
lights: [ambient, spot]
fps: 24
seconds: 1
animate:
  view_point:
    orbit: {center: [-10, -10, 16], sin: [20, 0, 0], cos: [0, 0, 15]}
  look_at: {toward: [0, 0, 0]}
EOF
"$firsthit" frames "$tmp/movie/tiny.yaml" --out "$tmp/reference" --quiet 2>/dev/null || fail "the single-machine run failed"
frames_made=$(ls "$tmp/reference" | grep -c '^frame_[0-9]*\.png$')  # beside them: frame_movie.txt
[[ $frames_made -eq 24 ]] || fail "the single-machine run made $frames_made frames, not 24"

# --- submit ----------------------------------------------------------------
out=$tmp/out/tiny
submitted=$(FIRSTHIT=$firsthit bash "$src/scripts/slurm_submit.sh" "$tmp/movie/tiny.yaml" "$out" 4 --cpus-per-task=1) ||
  fail "slurm_submit.sh failed"
array_job=$(awk '$1 == "render_job:" {print $2}' <<<"$submitted")
encode_job=$(awk '$1 == "encode_job:" {print $2}' <<<"$submitted")
[[ $array_job =~ ^[0-9]+$ && $encode_job =~ ^[0-9]+$ ]] || fail "slurm_submit.sh printed no job ids: $submitted"
log "submitted render job array $array_job (4 tasks) and encode job $encode_job"

# JobState of every line `scontrol show job ID -o` prints (one per array task).
states() { scontrol show job "$1" -o 2>/dev/null | grep -oE 'JobState=[A-Z_]+' | cut -d= -f2; }
job_done() {
  local s
  s=$(states "$encode_job")
  case $s in
    COMPLETED) return 0 ;;
    PENDING | RUNNING | COMPLETING | CONFIGURING) ;;
    *) fail "encode job $encode_job ended $s (render tasks: $(states "$array_job" | tr '\n' ' '))" ;;
  esac
  if states "$array_job" | grep -qvE '^(PENDING|RUNNING|COMPLETING|CONFIGURING|COMPLETED)$'; then
    fail "a render task failed: $(scontrol show job "$array_job" -o | grep -oE '(ArrayTaskId|JobState|ExitCode)=[^ ]+' | tr '\n' ' ')"
  fi
  return 1
}
wait_until 120 "the render tasks and the encode job" job_done
log "encode job completed"

# --- check -------------------------------------------------------------------
[[ $(states "$array_job" | sort | uniq -c | awk '{print $1, $2}') == "4 COMPLETED" ]] ||
  fail "render tasks: $(states "$array_job" | tr '\n' ' ')"
for k in 0 1 2 3; do
  f=$out.logs/render-${array_job}_$k.out
  [[ -f $f ]] || fail "no log of task $k ($f)"
  grep -q '^rendered 6 frames' "$f" || fail "task $k did not render 6 frames: $(cat "$f")"
done
probe=$(ffprobe -v error -select_streams v:0 -count_frames \
  -show_entries stream=codec_name,width,height,nb_read_frames -of default=noprint_wrappers=1 "$out.mp4") ||
  fail "ffprobe cannot read $out.mp4"
for want in codec_name=h264 width=64 height=64 nb_read_frames=24; do
  grep -qx "$want" <<<"$probe" || fail "$out.mp4: expected $want, ffprobe says: $(tr '\n' ' ' <<<"$probe")"
done
same_frames() {
  [[ $(ls "$out") == "$(ls "$tmp/reference")" ]] || fail "frame files differ from the single-machine run: $(ls "$out" | tr '\n' ' ')"
  for f in "$tmp/reference"/*; do
    cmp -s "$f" "$out/$(basename "$f")" || fail "$(basename "$f") differs from the single-machine run"
  done
}
same_frames
log "4 tasks, 24 frames identical to the single-machine run, MP4 h264 64x64 24 frames"

# --- requeue: a task run again renders only its missing frames -------------
rm "$out/frame_0005.png" "$out/frame_0009.png"  # 5 mod 4 = 9 mod 4 = 1: task 1's
scontrol requeue "${array_job}_1" || fail "scontrol requeue ${array_job}_1 failed"
requeued_done() {
  local s
  s=$(scontrol show job "${array_job}_1" -o 2>/dev/null)
  grep -q 'Restarts=1' <<<"$s" || fail "task 1 was not requeued: $s"
  case $(grep -oE 'JobState=[A-Z_]+' <<<"$s" | cut -d= -f2) in
    COMPLETED) return 0 ;;
    PENDING | RUNNING | COMPLETING | CONFIGURING | REQUEUED) return 1 ;;
    *) fail "requeued task 1: $s" ;;
  esac
}
wait_until 90 "requeued task ${array_job}_1" requeued_done
# The log of the rerun starts at render.sbatch's "restart 1" line.
sed -n '/restart 1$/,$p' "$out.logs/render-${array_job}_1.out" | grep -q '^rendered 2 frames' ||
  fail "the requeued task did not render exactly its 2 missing frames: $(cat "$out.logs/render-${array_job}_1.out")"
[[ $(grep -c '^render.sbatch: task 1 of 4' "$out.logs/render-${array_job}_1.out") -eq 2 ]] ||
  fail "task 1's log does not hold both runs (--open-mode=append): $(cat "$out.logs/render-${array_job}_1.out")"
same_frames
log "requeued task 1 rendered its 2 missing frames; all 24 identical again"

# --- a failed task: the encode job is cancelled; the same command run again
# renders only the missing frames, then encodes --------------------------
rm "$out/frame_0002.png" "$out/frame_0006.png" "$out.mp4"  # 2 and 6: task 2's
cat >"$tmp/failing_firsthit" <<EOF
#!/usr/bin/env bash
# firsthit, except that array task 2 fails.
[[ \${SLURM_ARRAY_TASK_ID:-} == 2 ]] && { echo "simulated failure of task 2" >&2; exit 1; }
exec "$firsthit" "\$@"
EOF
chmod +x "$tmp/failing_firsthit"
submit() {
  submitted=$(FIRSTHIT=$1 bash "$src/scripts/slurm_submit.sh" "$tmp/movie/tiny.yaml" "$out" 4 --cpus-per-task=1) ||
    fail "slurm_submit.sh failed"
  array_job=$(awk '$1 == "render_job:" {print $2}' <<<"$submitted")
  encode_job=$(awk '$1 == "encode_job:" {print $2}' <<<"$submitted")
}
submit "$tmp/failing_firsthit"
log "submitted render job array $array_job whose task 2 fails, encode job $encode_job"
encode_cancelled() {
  case $(states "$encode_job") in
    CANCELLED) return 0 ;;
    PENDING | RUNNING | COMPLETING | CONFIGURING) return 1 ;;
    *) fail "encode job $encode_job ended $(states "$encode_job"), not CANCELLED, after task 2 failed" ;;
  esac
}
wait_until 60 "the encode job to be cancelled after task 2 failed" encode_cancelled
tasks_settled() { ! states "$array_job" | grep -qE '^(PENDING|RUNNING|COMPLETING|CONFIGURING)$'; }
wait_until 30 "the failing job array to end" tasks_settled
[[ $(states "$array_job" | sort | uniq -c | awk '{print $1, $2}' | tr '\n' ' ') == "3 COMPLETED 1 FAILED " ]] ||
  fail "expected 3 completed tasks and 1 failed: $(states "$array_job" | tr '\n' ' ')"
[[ ! -e $out.mp4 ]] || fail "an MP4 was made although task 2 failed"
log "task 2 failed, the encode job was cancelled, no MP4"

submit "$firsthit"
wait_until 120 "the resubmitted render tasks and encode job" job_done
for k in 0 1 3; do
  grep -q '^rendered 0 frames' "$out.logs/render-${array_job}_$k.out" ||
    fail "task $k rendered frames again: $(cat "$out.logs/render-${array_job}_$k.out")"
done
grep -q '^rendered 2 frames' "$out.logs/render-${array_job}_2.out" ||
  fail "task 2 did not render its 2 missing frames: $(cat "$out.logs/render-${array_job}_2.out")"
same_frames
[[ -s $out.mp4 ]] || fail "no MP4 after the resubmission"
log "resubmitted: task 2 rendered its 2 frames, the others none; MP4 made; all 24 identical"
echo "PASS: slurm.job_array in $((SECONDS - start_time)) s"
