#!/usr/bin/env bash
#SBATCH --job-name=dem-sweep
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
# One task of a sweep: runs case cases/NNNN.case.txtpb of a sweep directory
# headless with the one-shot server (dem_server --case ... --run-and-exit),
# so it can be watched over DDS while it runs, and writes its results, final
# snapshot and status to tasks/NNNN/ (docs/SWEEPS.md has the directory's
# layout). Every backend runs tasks through this script: a Slurm job array,
#   sbatch --array=0-7 --output=SWEEP/logs/slurm-%A_%a.out scripts/slurm/dem_sweep_task.sh SWEEP
# dem.sweep's local processes and Dask workers (dem_sweep_task.sh SWEEP INDEX).
#
# A task that is done (status done, final snapshot there) is not run again,
# so resubmitting the whole array runs only what did not finish. A task
# whose server wrote checkpoints (sweep.conf checkpoint_cycles or
# checkpoint_seconds) continues from its newest one (dem_server --resume);
# any other task starts afresh. SIGTERM and SIGINT (scancel, a time limit,
# Ctrl-C) reach the server, which stops after its current chunk of cycles
# with a final snapshot (exit 4, status "stopped").
#
# A task runs once at a time: it holds tasks/NNNN/task.lock (flock) while
# it runs, and so does its server, so a second copy (a resubmission while
# the first still runs) exits 75 and leaves the first alone.
#
# Exit code: the server's (0 done, 1 failed, 3 invalid case, 4 stopped, 5
# another server holds its name; docs/SERVICE.md; 1 also when it exited 0
# without its final snapshot), 2 when the sweep directory or the index is
# wrong, 75 when the task is running already.
set -uo pipefail

status_file=""
# An error before the server starts; once the task is known, its status says it too.
fail() {
  echo "dem_sweep_task: $*" >&2
  if [ -n "$status_file" ] && mkdir -p "${status_file%/*}" 2>/dev/null; then
    printf 'state=failed\nexit_code=2\nerror=%s\n' "$*" >"$status_file.tmp" && mv -f "$status_file.tmp" "$status_file"
  fi
  exit 2
}

[ $# -ge 1 ] && [ $# -le 2 ] || fail "usage: dem_sweep_task.sh SWEEP_DIR [INDEX] (INDEX defaults to \$SLURM_ARRAY_TASK_ID)"
[ -d "$1" ] || fail "no sweep directory $1"
sweep="$(cd "$1" && pwd)"
index="${2:-${SLURM_ARRAY_TASK_ID:-}}"
[ -n "$index" ] || fail "no task index: give one, or run as a Slurm array task"
[[ "$index" =~ ^[0-9]+$ ]] || fail "task index \"$index\" is not a number"
index=$((10#$index))

# sweep.conf: KEY=VALUE lines written by dem.sweep (or by hand), read here
# without executing anything.
name="" domain="" tasks="" server_program="" dds_config="" threads=1 telemetry_cycles=100
checkpoint_cycles=0 checkpoint_seconds=0 log_level=info
[ -f "$sweep/sweep.conf" ] || fail "$sweep/sweep.conf is missing: not a sweep directory"
line_number=0
while IFS= read -r line || [ -n "$line" ]; do
  line_number=$((line_number + 1))
  [[ "$line" =~ ^[[:space:]]*(#.*)?$ ]] && continue
  [[ "$line" =~ ^([a-z_]+)=(.*)$ ]] || fail "$sweep/sweep.conf:$line_number: expected KEY=VALUE, got \"$line\""
  key="${BASH_REMATCH[1]}" value="${BASH_REMATCH[2]}"
  case "$key" in
    name | domain | tasks | server_program | dds_config | threads | telemetry_cycles | checkpoint_cycles | \
      checkpoint_seconds | log_level) printf -v "$key" '%s' "$value" ;;
    *) fail "$sweep/sweep.conf:$line_number: unknown key \"$key\"" ;;
  esac
done <"$sweep/sweep.conf"
[[ "$name" =~ ^[A-Za-z][A-Za-z0-9_]{0,58}$ ]] ||
  fail "$sweep/sweep.conf: name \"$name\" must be a letter, then letters, digits or underscores (at most 59)"
[[ "$domain" =~ ^[0-9]+$ ]] && [ "$domain" -le 232 ] || fail "$sweep/sweep.conf: domain \"$domain\" must be 0 to 232"
[[ "$tasks" =~ ^[0-9]+$ ]] || fail "$sweep/sweep.conf: tasks \"$tasks\" must be a count"
for key in threads telemetry_cycles checkpoint_cycles; do
  [[ "${!key}" =~ ^[0-9]+$ ]] || fail "$sweep/sweep.conf: $key \"${!key}\" must be a whole number"
done
[[ "$checkpoint_seconds" =~ ^[0-9]+(\.[0-9]+)?$ ]] || fail "$sweep/sweep.conf: checkpoint_seconds must be a number"
[ "$index" -lt "$tasks" ] || fail "task $index does not exist: the sweep has $tasks tasks (0 to $((tasks - 1)))"

task_id=$(printf '%04d' "$index")
case_file="$sweep/cases/$task_id.case.txtpb"
out="$sweep/tasks/$task_id"
mkdir -p "$out" || fail "cannot make $out"
exec 9>>"$out/task.lock"
# A few seconds' grace: dem.sweep probes the lock for an instant to see whether a task runs.
if ! flock -w 5 9; then
  echo "dem_sweep_task: task $task_id is running already (another process holds $out/task.lock)" >&2
  exit 75
fi
status_file="$out/task.status"
[ -f "$case_file" ] || fail "$case_file is missing"
server="${DEM_SERVER_PROGRAM:-${server_program:-dem_server}}"
command -v "$server" >/dev/null || fail "no dem_server at \"$server\" (sweep.conf server_program, or \$DEM_SERVER_PROGRAM)"
[ -n "$dds_config" ] && export CYCLONEDDS_URI="$dds_config"

status_value() { sed -n "s/^$1=//p" "$status_file" 2>/dev/null | tail -1; }
now() { date -u +%Y-%m-%dT%H:%M:%SZ; }
# The status file is replaced whole (written aside, renamed), so a reader
# never sees half of one.
write_status() {
  {
    for pair in "$@"; do echo "$pair"; done
  } >"$status_file.tmp" && mv -f "$status_file.tmp" "$status_file"
}

if [ "$(status_value state)" = done ] && compgen -G "$out/*/final.snapshot" >/dev/null; then
  echo "dem_sweep_task: task $task_id of $name is done already ($status_file)"
  exit 0
fi

previous_attempt="$(status_value attempt)"
attempt=$((${previous_attempt:-0} + 1))
resume=()
if [ "$checkpoint_cycles" -gt 0 ] || ! [[ "$checkpoint_seconds" =~ ^0*(\.0*)?$ ]]; then
  # (Read whole: grep -q in a pipe would end it early, and pipefail call that a failure.)
  server_help="$("$server" --help 2>/dev/null)"
  [[ "$server_help" == *--checkpoint-cycles* ]] ||
    fail "sweep.conf asks for checkpoints, but $server has no --checkpoint-cycles"
  checkpoints=(--checkpoint-cycles "$checkpoint_cycles" --checkpoint-seconds "$checkpoint_seconds")
  # The server keeps its checkpoints in <out>/<case name>/checkpoints; a
  # checkpoint is whole once its .resume file is there (written last).
  if compgen -G "$out/*/checkpoints/*.resume" >/dev/null; then
    resume=(--resume)
  fi
else
  checkpoints=()
fi
if [ ${#resume[@]} -eq 0 ]; then
  # A fresh start: an earlier attempt's tables would be mixed with this one's.
  for previous in "$out"/*/; do
    [ -d "$previous" ] && rm -rf "$previous"
  done
fi

server_name="${name}_$task_id"
started="$(now)"
write_status "state=running" "attempt=$attempt" "server=$server_name" "host=$(hostname -s)" "pid=$$" \
  "slurm_job=${SLURM_JOB_ID:-}" "slurm_array_job=${SLURM_ARRAY_JOB_ID:-}" "resumed=$([ ${#resume[@]} -gt 0 ] && echo yes || echo no)" \
  "started=$started"
echo "dem_sweep_task: task $task_id of $name (attempt $attempt${resume:+, resumed}) as server $server_name on domain $domain, host $(hostname -s)" \
  | tee -a "$out/dem_server.log"

# The server runs as a child so this script outlives it and records how it
# ended; SIGTERM and SIGINT are passed on (a scheduler may signal this shell
# alone, e.g. sbatch --signal=B:TERM@120).
"$server" --name "$server_name" --domain "$domain" --case "$case_file" --run-and-exit --out "$out" \
  --threads "$threads" --telemetry-cycles "$telemetry_cycles" --log-level "$log_level" \
  "${checkpoints[@]}" "${resume[@]}" >>"$out/dem_server.log" 2>&1 &
server_pid=$!
forward() { kill -s "$1" "$server_pid" 2>/dev/null; }
trap 'forward TERM' TERM
trap 'forward INT' INT
# wait returns early when a trapped signal arrives: wait again until the server has exited.
while :; do
  wait "$server_pid"
  code=$?
  kill -0 "$server_pid" 2>/dev/null || break
done

case $code in
  0) state=done ;;
  4) state=stopped ;;
  *) state=failed ;;
esac
if [ $state = done ] && ! compgen -G "$out/*/final.snapshot" >/dev/null; then
  state=failed  # exit 0 without its final snapshot is no success
  code=1
fi
write_status "state=$state" "exit_code=$code" "attempt=$attempt" "server=$server_name" "host=$(hostname -s)" \
  "slurm_job=${SLURM_JOB_ID:-}" "slurm_array_job=${SLURM_ARRAY_JOB_ID:-}" \
  "resumed=$([ ${#resume[@]} -gt 0 ] && echo yes || echo no)" "started=$started" "ended=$(now)"
echo "dem_sweep_task: task $task_id of $name: $state (exit $code)" | tee -a "$out/dem_server.log"
exit $code
