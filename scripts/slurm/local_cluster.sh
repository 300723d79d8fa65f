#!/usr/bin/env bash
# A real Slurm cluster of one controller and one node on this machine, for
# tests and for trying the sweep scripts (../shared/SLURM.md is the verified
# recipe; docs/SWEEPS.md). Everything it makes lives in DIR: its own munged
# (own key, socket and pid file, so a munge the machine already runs is left
# alone), slurm.conf, the controller's and node's state, spool, logs and pid
# files, and jobcomp.txt, one line per finished task with its exit code (the
# stand-in for accounting, which needs slurmdbd). Slurm listens on 127.0.0.1
# only, on its usual ports 6817 and 6818, so one such cluster runs at a time.
#
#   local_cluster.sh start DIR   start munged, slurmctld and slurmd; wait until the node is idle
#   local_cluster.sh stop DIR    cancel every job, stop the three daemons, wait until they are gone
#   local_cluster.sh env DIR     print "export SLURM_CONF=DIR/slurm.conf" for sbatch, squeue, ...
#
# Needs root (slurmd runs jobs as their users) and the packages slurmctld,
# slurmd, slurm-client and munge (scripts/install_deps.sh). start and stop
# are idempotent; stop also cleans up after a start that failed half-way.
set -euo pipefail

usage() { echo "usage: local_cluster.sh start|stop|env DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action="$1"
mkdir -p "$2"
dir="$(cd "$2" && pwd)"
export SLURM_CONF="$dir/slurm.conf"

log() { echo "local_cluster: $*" >&2; }

# A pid file's process if it is alive. PID 1 here reaps exited daemons only
# every few seconds, so kill -0 succeeds on a zombie: read its state instead.
alive_pid() {
  local pid
  pid=$(cat "$1" 2>/dev/null) || return 1
  [ -n "$pid" ] && [ -r "/proc/$pid/status" ] || return 1
  ! grep -q '^State:[[:space:]]*Z' "/proc/$pid/status" 2>/dev/null || return 1
  echo "$pid"
}

# wait_until SECONDS WHAT COMMAND...: poll COMMAND every 0.1 s.
wait_until() {
  local seconds="$1" what="$2"
  shift 2
  local deadline=$((SECONDS + seconds))
  until "$@" >/dev/null 2>&1; do
    if [ $SECONDS -ge $deadline ]; then
      log "gave up after ${seconds} s waiting for $what"
      return 1
    fi
    sleep 0.1
  done
}

stop_pid_file() {  # stop_pid_file NAME FILE: SIGTERM, then SIGKILL after 10 s
  local pid
  pid=$(alive_pid "$2") || { rm -f "$2"; return 0; }
  kill -TERM "$pid" 2>/dev/null || true
  if ! wait_until 10 "$1 to exit" eval "! alive_pid '$2'"; then
    kill -KILL "$pid" 2>/dev/null || true
    wait_until 5 "$1 to die" eval "! alive_pid '$2'" || true
  fi
  rm -f "$2"
}

write_munge_key() {
  # The cluster's own key: 1024 random bytes, readable by munged alone.
  install -d -o munge -g munge -m 0700 "$dir/munge"
  if [ ! -s "$dir/munge/munge.key" ]; then
    head -c 1024 /dev/urandom >"$dir/munge/munge.key"
    chown munge:munge "$dir/munge/munge.key"
    chmod 0400 "$dir/munge/munge.key"
  fi
}

write_slurm_conf() {
  local host topology memory_mb
  host="$(hostname -s)"
  # The node's topology as slurmd sees it; RealMemory at 75% of what it
  # reports (more than the machine has puts the node in state inval for good).
  topology="$(slurmd -C | head -1 | tr ' ' '\n' |
    grep -E '^(CPUs|Boards|SocketsPerBoard|CoresPerSocket|ThreadsPerCore)=' | tr '\n' ' ')"
  memory_mb=$(slurmd -C | head -1 | tr ' ' '\n' | sed -n 's/^RealMemory=//p')
  memory_mb=$((memory_mb * 3 / 4))
  install -d -m 0755 "$dir/state" "$dir/spool" "$dir/log"
  cat >"$dir/slurm.conf" <<EOF
# Written by scripts/slurm/local_cluster.sh: one controller and one node on
# 127.0.0.1, no cgroups, no accounting database.
ClusterName=demtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=6817
SlurmdPort=6818
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.txt
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerParameters=batch_sched_delay=0
MinJobAge=3600
# A cancelled task gets SIGTERM, then SIGKILL this many seconds later: long
# enough for dem_server to finish its chunk and write its final snapshot.
KillWait=10
MailProg=/bin/true
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 ${topology}RealMemory=$memory_mb State=UNKNOWN
PartitionName=main Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
}

port_in_use() { ss -Hltn "sport = :$1" 2>/dev/null | grep -q .; }

start() {
  [ "$(id -u)" -eq 0 ] || { log "needs root (slurmd runs jobs as their users)"; exit 1; }
  local program
  for program in munged slurmctld slurmd sbatch; do
    command -v "$program" >/dev/null || { log "$program is missing: run scripts/install_deps.sh"; exit 1; }
  done

  # munged runs as the user munge, which must reach DIR (a private temporary directory will not do).
  runuser -u munge -- test -x "$dir" ||
    { log "the user munge cannot enter $dir: use a directory every user may traverse"; exit 1; }
  write_munge_key
  if ! alive_pid "$dir/munge/munged.pid" >/dev/null; then
    runuser -u munge -- munged --force --socket="$dir/munge/munge.socket" \
      --key-file="$dir/munge/munge.key" --pid-file="$dir/munge/munged.pid" \
      --seed-file="$dir/munge/munged.seed" --log-file="$dir/munge/munged.log"
  fi
  wait_until 10 "munged" eval "munge -n -S '$dir/munge/munge.socket' | unmunge -S '$dir/munge/munge.socket'"

  write_slurm_conf
  if ! alive_pid "$dir/slurmctld.pid" >/dev/null; then
    if port_in_use 6817; then
      log "port 6817 is taken: another slurmctld runs on this machine (stop it first)"
      exit 1
    fi
    slurmctld -c -f "$SLURM_CONF"  # -c: no state from an earlier run
  fi
  wait_until 20 "slurmctld" eval "scontrol ping | grep -q UP"
  if ! alive_pid "$dir/slurmd.pid" >/dev/null; then
    port_in_use 6818 && { log "port 6818 is taken: another slurmd runs on this machine"; exit 1; }
    slurmd -f "$SLURM_CONF"
  fi
  wait_until 30 "the node to be idle" eval "sinfo -h -N -o %T | grep -qx idle"
  log "up: export SLURM_CONF=$SLURM_CONF"
}

# Job processes that outlived a failed cancel: those with this cluster's
# configuration and a job id in their environment (jobs inherit the
# submitter's SLURM_CONF), and nothing else.
kill_leftover_jobs() {
  local environ pid text
  for environ in /proc/[0-9]*/environ; do
    pid="${environ#/proc/}"
    pid="${pid%/environ}"
    text="$( { tr '\0' '\n' <"$environ"; } 2>/dev/null)" || continue
    grep -qx "SLURM_CONF=$SLURM_CONF" <<<"$text" || continue
    grep -q '^SLURM_JOB_ID=' <<<"$text" || continue
    log "killing job process $pid left behind"
    kill -KILL "$pid" 2>/dev/null || true
  done
}

stop() {
  # Running jobs survive the controller's shutdown: cancel them first.
  if [ -f "$SLURM_CONF" ] && alive_pid "$dir/slurmctld.pid" >/dev/null; then
    scancel --full --quiet --user="$(id -un)" 2>/dev/null || true
    scancel --full --quiet 2>/dev/null || true
    wait_until 20 "the jobs to end" eval "[ -z \"\$(squeue -h 2>/dev/null)\" ]" || true
    scontrol shutdown >/dev/null 2>&1 || true
  fi
  stop_pid_file slurmd "$dir/slurmd.pid"
  kill_leftover_jobs
  stop_pid_file slurmctld "$dir/slurmctld.pid"
  stop_pid_file munged "$dir/munge/munged.pid"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  env) echo "export SLURM_CONF=$SLURM_CONF" ;;
  *) usage ;;
esac
