#!/usr/bin/env bash
# A sweep as a Slurm job array, as docs/SWEEPS.md tells a user to run it, on
# a real Slurm cluster started here (scripts/slurm/local_cluster.sh: munged,
# slurmctld and slurmd on 127.0.0.1):
#   1. a sweep of Miyata's reduced CS case over four frictions, made with
#      dem.sweep, one task's case spoilt on purpose;
#   2. sbatch --array=0-3 of the sweep's task script, watched meanwhile by
#      demctl monitor --sweep; every task's exit code in Slurm and its status;
#      the three good tasks' outputs (tables, final snapshot, the plate at
#      900 kPa), the bad one reported failed with its reason
#      (python3 -m dem.sweep status);
#   3. the case mended and that task resubmitted alone (sbatch --array=2):
#      done, on its second attempt, the others untouched; then the whole
#      array resubmitted: nothing runs again;
#   4. the results gathered (summary.csv);
#   5. a checkpointed task resumes: a sweep that keeps checkpoints, two
#      identical tasks; one is killed (SIGKILL to its script and server, as
#      a crash would) after some checkpoints, resubmitted alone, resumes from its
#      newest checkpoint and ends with the same tables and final state as
#      its twin that ran straight through.
# Needs root (slurmd); exits 77 (a skip) otherwise.
#   slurm_array_test.sh SOURCE_DIR WORK_DIR DOMAIN DEMCTL
set -euo pipefail
source_dir=$1 work=$2 domain=$3 demctl=$4
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: a Slurm node runs jobs as their users: this test needs root"
  exit 77
fi
cluster="$work/cluster" sweep="$work/sweep"
local_cluster="$source_dir/scripts/slurm/local_cluster.sh"
[ -d "$cluster" ] && bash "$local_cluster" stop "$cluster"
rm -rf "$work" && mkdir -p "$work"
monitor=""
cleanup() {
  [ -n "$monitor" ] && kill "$monitor" 2>/dev/null
  bash "$local_cluster" stop "$cluster"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  for log in "$sweep"/logs/* "$cluster"/log/*; do [ -f "$log" ] && tail -5 "$log" | sed "s|^|  $(basename "$log") |" >&2; done
  exit 1
}
python=/usr/bin/python3

started=$SECONDS
bash "$local_cluster" start "$cluster"
export SLURM_CONF="$cluster/slurm.conf"
echo "ok: Slurm up in $((SECONDS - started)) s: $(sinfo -h -N -o '%N %T %c CPUs')"

# 1. The sweep, and task 2's case spoilt (a field the schema does not have).
"$python" - "$sweep" "$domain" <<'PY'
import sys
import dem, dem.sweep
sweep = dem.sweep.Sweep.create(sys.argv[1], dem.paths.cases_dir() / "miyata" / "cs_reduced.case.txtpb",
                               {"material[*].friction": [0.3, 0.45, 0.6, 0.75]}, name="slurm_cs",
                               domain=int(sys.argv[2]))
print(f"ok: {sweep}")
PY
cp "$sweep/cases/0002.case.txtpb" "$work/0002.case.txtpb"
echo 'no_such_field: 1' >>"$sweep/cases/0002.case.txtpb"

# 2. The array, as the docs say; a monitor follows its servers meanwhile.
"$demctl" --domain "$domain" monitor --sweep slurm_cs --csv "$work/monitor.csv" >"$work/monitor.out" 2>"$work/monitor.err" &
monitor=$!
wait_for_job() {  # wait_for_job ID: until Slurm has it no more (squeue failing is an error, not an end)
  local deadline=$((SECONDS + 180)) queued
  while queued=$(squeue -h -j "$1" -o %i) && [ -n "$queued" ]; do
    [ $SECONDS -lt $deadline ] || fail "job $1 still queued after 180 s: $(squeue -j "$1")"
    sleep 0.5
  done
  [ -z "$queued" ] || fail "squeue failed for job $1"
}
exit_code() {  # exit_code JOB TASK: Slurm's ExitCode=code:signal of one array task
  scontrol -o show job "$1" | grep " ArrayTaskId=$2 " | sed -n 's/.* ExitCode=\([0-9:]*\).*/\1/p'
}
state() { sed -n 's/^state=//p' "$sweep/tasks/$1/task.status"; }
attempt() { sed -n 's/^attempt=//p' "$sweep/tasks/$1/task.status"; }

started=$SECONDS
job=$(sbatch --parsable --array=0-3 --output="$sweep/logs/slurm-%A_%a.out" "$sweep/dem_sweep_task.sh" "$sweep")
wait_for_job "$job"
echo "ok: job array $job ran its four tasks in $((SECONDS - started)) s"
for task in 0 1 3; do
  [ "$(exit_code "$job" $task)" = "0:0" ] || fail "task $task: Slurm says ExitCode=$(exit_code "$job" $task)"
  id=$(printf %04d $task)
  [ "$(state "$id")" = done ] || fail "task $id: state $(state "$id")"
  out="$sweep/tasks/$id/miyata_cs_reduced"
  for file in final.snapshot walls.csv assembly.csv stages.csv compression.csv; do
    [ -s "$out/$file" ] || fail "task $id has no $file"
  done
  grep -q "^server=slurm_cs_$id$" "$sweep/tasks/$id/task.status" || fail "task $id's server is not slurm_cs_$id"
  grep -q "^slurm_array_job=$job$" "$sweep/tasks/$id/task.status" || fail "task $id's status names no job $job"
  # The plate reached the case's 900 kPa.
  tail -1 "$out/compression.csv" | awk -F, '{ exit !($5 >= 9e5) }' || fail "task $id ends below 900 kPa"
done
[ "$(exit_code "$job" 2)" = "3:0" ] || fail "task 2: Slurm says ExitCode=$(exit_code "$job" 2), expected 3:0 (invalid case)"
[ "$(state 0002)" = failed ] || fail "task 0002: state $(state 0002), expected failed"
echo "ok: tasks 0, 1, 3 done with their outputs; task 2 failed with exit 3 (Slurm ExitCode=3:0)"

code=0
"$python" -m dem.sweep status "$sweep" >"$work/status.txt" || code=$?
[ $code -eq 1 ] || fail "dem.sweep status exited $code with a task failed, expected 1"
grep -q "task 0002 failed (exit 3)" "$work/status.txt" || fail "dem.sweep status does not report task 2: $(cat "$work/status.txt")"
# Why: the case file and its line (the server quotes none of a file's content).
bad_line=$(wc -l <"$sweep/cases/0002.case.txtpb")
grep -q "0002.case.txtpb:$bad_line:" "$work/status.txt" || fail "the report does not say why: $(cat "$work/status.txt")"
echo "ok: dem.sweep status reports task 0002 failed and why"

# 3. Mended and resubmitted alone; then the whole array again.
cp "$work/0002.case.txtpb" "$sweep/cases/0002.case.txtpb"
before=$(stat -c %Y "$sweep"/tasks/000[013]/miyata_cs_reduced/final.snapshot)
job2=$(sbatch --parsable --array=2 --output="$sweep/logs/slurm-%A_%a.out" "$sweep/dem_sweep_task.sh" "$sweep")
wait_for_job "$job2"
[ "$(exit_code "$job2" 2)" = "0:0" ] || fail "resubmitted task 2: ExitCode=$(exit_code "$job2" 2)"
[ "$(state 0002)" = done ] && [ "$(attempt 0002)" = 2 ] || fail "task 0002: $(state 0002), attempt $(attempt 0002)"
[ -s "$sweep/tasks/0002/miyata_cs_reduced/final.snapshot" ] || fail "task 0002 has no final snapshot"
job3=$(sbatch --parsable --array=0-3 --output="$sweep/logs/slurm-%A_%a.out" "$sweep/dem_sweep_task.sh" "$sweep")
wait_for_job "$job3"
for task in 0000 0001 0002 0003; do
  expected=1 && [ $task = 0002 ] && expected=2
  [ "$(attempt $task)" = $expected ] || fail "task $task ran again (attempt $(attempt $task))"
done
grep -q "is done already" "$sweep/logs/slurm-${job3}_0.out" || fail "the resubmitted array did not say task 0 was done"
[ "$before" = "$(stat -c %Y "$sweep"/tasks/000[013]/miyata_cs_reduced/final.snapshot)" ] ||
  fail "the resubmissions touched the tasks that were done"
echo "ok: task 2 resubmitted alone is done on its second attempt; the whole array resubmitted runs nothing again"

# 4. The results, and what the monitor saw.
"$python" -m dem.sweep results "$sweep" >"$work/summary.txt" || fail "dem.sweep results exited $?"
[ "$(grep -c ",done," "$sweep/summary.csv")" -eq 4 ] || fail "summary.csv: $(cat "$sweep/summary.csv")"
kill -TERM "$monitor" && wait "$monitor" || fail "the monitor exited $?"
monitor=""
seen=$(tail -n +2 "$work/monitor.csv" | cut -d, -f1 | sort -u | tr '\n' ' ')
[ "$(echo "$seen" | wc -w)" -ge 3 ] || fail "demctl monitor --sweep saw only: $seen"
echo "ok: summary.csv has the four tasks done; demctl monitor --sweep saw $seen"

# 5. A checkpointed task resumes. Slower plates (0.01 m/s), so the tasks run
# long enough to be caught; a checkpoint every 5,000 cycles.
resume="$work/resume"
"$python" - "$resume" "$domain" <<'PY'
import sys
import dem, dem.sweep
dem.sweep.Sweep.create(sys.argv[1], dem.paths.cases_dir() / "miyata" / "cs_reduced.case.txtpb",
                       {"material[*].friction": [0.45, 0.45], "stage[2].wall[0].motion.velocity.y": [-0.01]},
                       name="slurm_resume", domain=int(sys.argv[2]), checkpoint_cycles=5000)
PY
job4=$(sbatch --parsable --array=0-1 --output="$resume/logs/slurm-%A_%a.out" "$resume/dem_sweep_task.sh" "$resume")
checkpoints="$resume/tasks/0000/miyata_cs_reduced/checkpoints"
newest_checkpoint() { ls "$checkpoints"/*.resume 2>/dev/null | tail -1 | sed 's/.*checkpoint-0*\([0-9]*\)\.resume/\1/'; }
# Caught in the loading stage (from about cycle 22,600), where the plate loading analyses run too.
deadline=$((SECONDS + 120))
until [ "$(newest_checkpoint)" -ge 30000 ] 2>/dev/null; do
  [ $SECONDS -lt $deadline ] || fail "task 0 wrote no checkpoints in 120 s"
  [ "$(sed -n 's/^state=//p' "$resume/tasks/0000/task.status" 2>/dev/null)" != done ] || fail "task 0 ended before it could be killed"
  sleep 0.2
done
# SIGKILL to the task's script and its server, as a crash would leave them
# (scancel --signal=KILL would first send SIGTERM, which stops the server cleanly).
script_pid=$(sed -n 's/^pid=//p' "$resume/tasks/0000/task.status")
server_pid=$(grep -l "^PPid:[[:space:]]*$script_pid\$" /proc/[0-9]*/status 2>/dev/null | head -1 | cut -d/ -f3)
[ -n "$script_pid" ] && [ -n "$server_pid" ] || fail "task 0's script ($script_pid) or server ($server_pid) not found"
kill -KILL "$server_pid" "$script_pid"
wait_for_job "$job4"
killed_at=$(newest_checkpoint)
grep -q "^state=running$" "$resume/tasks/0000/task.status" || fail "the killed task's status: $(cat "$resume/tasks/0000/task.status")"
"$python" -m dem.sweep status "$resume" >"$work/resume_status.txt" || true
grep -q "slurm_resume_0000" "$work/resume_status.txt" && grep -q "interrupted" "$work/resume_status.txt" ||
  fail "dem.sweep status does not call the killed task interrupted: $(cat "$work/resume_status.txt")"
[ "$(sed -n 's/^state=//p' "$resume/tasks/0001/task.status")" = done ] || fail "the twin did not finish"
echo "ok: task 0 killed (SIGKILL) with its newest checkpoint at cycle $killed_at; dem.sweep status says interrupted"
# Resubmitted alone. Its server waits out the killed one's DDS lease (about 10 s) before it takes the name.
job5=$(sbatch --parsable --array=0 --output="$resume/logs/slurm-%A_%a.out" "$resume/dem_sweep_task.sh" "$resume")
wait_for_job "$job5"
status="$resume/tasks/0000/task.status"
grep -q "^state=done$" "$status" && grep -q "^resumed=yes$" "$status" && grep -q "^attempt=2$" "$status" ||
  fail "the resubmitted task: $(cat "$status")"
grep -q "resuming from the checkpoint at cycle $killed_at" "$resume/tasks/0000/dem_server.log" ||
  fail "the server's log does not say it resumed at cycle $killed_at"
for table in walls.csv assembly.csv stages.csv compression.csv compression_states.csv final.snapshot; do
  cmp -s "$resume/tasks/0000/miyata_cs_reduced/$table" "$resume/tasks/0001/miyata_cs_reduced/$table" ||
    fail "the resumed task's $table differs from its uninterrupted twin's"
done
echo "ok: resubmitted, task 0 resumed from cycle $killed_at and ended with the tables and final snapshot of its twin"
