#!/usr/bin/env bash
# A headless experiment driven by demctl: the compose file's client service
# (as dem-experiment in the image), and what the container test runs on the
# host against a server in a container. It
#   1. waits for the server and loads a case (demctl sends the file's text);
#   2. starts `demctl monitor`, which records each plate's stress and
#      settlement and the contact statistics to CSV at every telemetry sample;
#   3. runs a loading stage: the plate moves at a constant velocity for a
#      number of cycles, then stands while the assembly comes to rest;
#   4. saves the plate's contacts and a snapshot here, another snapshot on the
#      server's side (in its output directory), prints the status;
#   5. stops the server (the monitor ends with it).
# Environment, with defaults:
#   DEM_SERVER, DEM_DOMAIN  the server to drive (demctl reads them)       dem, 0
#   EXPERIMENT_CASE      a case file on this side          the image's nine-disc test
#   EXPERIMENT_PLATE     the loading plate                                 top
#   EXPERIMENT_VELOCITY  its velocity during the stage, "VX VY" in m/s     0 -12
#   EXPERIMENT_CYCLES    the loading stage's length in cycles              40
#   EXPERIMENT_HOLD      cycles with the plate stopped afterwards          460
#   EXPERIMENT_OUT       where monitor.csv, contacts.csv and the snapshot go  /data/experiment
#   EXPERIMENT_SHUTDOWN  1 stops the server at the end, 0 leaves it running   1
#   EXPERIMENT_WAIT      seconds to wait for the server to appear         60
#   DEMCTL               the demctl program                                demctl
# Exits with demctl's code when a step fails (docs/SERVICE.md lists them).
set -euo pipefail

demctl="${DEMCTL:-demctl}"
case_file="${EXPERIMENT_CASE:-/opt/dem/cases/ball/nine_disc_damped.case.txtpb}"
plate="${EXPERIMENT_PLATE:-top}"
read -r vx vy <<<"${EXPERIMENT_VELOCITY:-0 -12}"
cycles="${EXPERIMENT_CYCLES:-40}"
hold="${EXPERIMENT_HOLD:-460}"
out="${EXPERIMENT_OUT:-/data/experiment}"
shutdown="${EXPERIMENT_SHUTDOWN:-1}"
wait_seconds="${EXPERIMENT_WAIT:-60}"
server="${DEM_SERVER:-dem}"

step() { printf '== %s\n' "$*"; }
monitor_pid=""
cleanup() { [ -z "$monitor_pid" ] || kill "$monitor_pid" 2>/dev/null || true; }
trap cleanup EXIT

mkdir -p "$out"
step "waiting for server $server on domain ${DEM_DOMAIN:-0}"
"$demctl" --timeout "$wait_seconds" status >/dev/null

step "loading $case_file"
"$demctl" load "$case_file"

step "recording the monitor to $out/monitor.csv"
"$demctl" monitor --wall "$plate" --csv "$out/monitor.csv" 2>"$out/monitor.log" &
monitor_pid=$!
for _ in $(seq 200); do grep -q monitoring "$out/monitor.log" 2>/dev/null && break; sleep 0.05; done
grep -q monitoring "$out/monitor.log" || { cat "$out/monitor.log" >&2; echo "the monitor did not start" >&2; exit 1; }
sleep 0.5  # the subscription matches the server's writers before the stage starts

step "loading stage: $plate moves at ($vx, $vy) m/s for $cycles cycles, then stands for $hold"
"$demctl" wall-velocity "$plate" "$vx" "$vy"
"$demctl" --quiet cycle "$cycles" --wait
"$demctl" wall-velocity "$plate" 0 0
"$demctl" --quiet cycle "$hold" --wait

step "results"
"$demctl" contacts --wall "$plate" --csv "$out/contacts.csv" --limit 5
"$demctl" snapshot save "$out/final.snapshot"
"$demctl" snapshot save experiment.snapshot --on-server
"$demctl" status

if [ "$shutdown" = 1 ]; then
  step "stopping the server"
  "$demctl" shutdown
  # The monitor ends by itself once the server is gone, with its last rows written.
  wait "$monitor_pid"
  monitor_pid=""
else
  sleep 0.5
  kill -INT "$monitor_pid"
  wait "$monitor_pid" || true
  monitor_pid=""
fi
cat "$out/monitor.log"
