#!/usr/bin/env bash
# The main job: the simulation service. Builds the project, starts dem_server
# on loopback, and drives a loading test with demctl while `demctl monitor`
# shows plate stress against settlement live:
#   1. load BALL's photoelastic verification assembly (197 discs, Cundall &
#      Strack 1979) and consolidate it: four servo-controlled walls at
#      500 kPa vertical and 200 kPa horizontal (the case's F_H/F_V = 0.4);
#   2. a biaxial loading stage: the top plate moves down at a constant
#      speed while the side walls hold their 200 kPa, until the plate
#      carries 1.5 MPa, three times its consolidation stress (run-until);
#   3. write the results (monitor table, contacts, snapshot, the server's
#      tables) and stop the server cleanly.
# Outputs go to out/service/ (or the directory given as $1).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(mkdir -p "${1:-$root/out}/service" && cd "${1:-$root/out}/service" && pwd)"
bash "$root/scripts/build.sh"

# Loopback only: 127.0.0.1, multicast off, peers on localhost.
export CYCLONEDDS_URI="file://$root/config/cyclonedds-loopback.xml"
export DEM_SERVER=demo DEM_DOMAIN="${DEM_DEMO_DOMAIN:-30}"
demctl="$root/build/clients/cpp/demctl/demctl"
server_pid=""
monitor_pid=""
cleanup() {
  for pid in $monitor_pid $server_pid; do kill -9 "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT
step() { printf '\n== %s\n' "$*"; }

rm -rf "$out" && mkdir -p "$out"
step "starting dem_server \"$DEM_SERVER\" on DDS domain $DEM_DOMAIN (log: $out/dem_server.log)"
"$root/build/service/dem_server" --name "$DEM_SERVER" --domain "$DEM_DOMAIN" --out "$out" \
  --telemetry-cycles 500 >"$out/dem_server.log" 2>&1 &
server_pid=$!
"$demctl" --timeout 20 servers

step "loading the verification assembly"
"$demctl" --timeout 20 load "$root/cases/ball/verification_assembly.case.txtpb"

step "consolidating: four servo walls, 500 kPa vertical, 200 kPa horizontal"
# The case's servo gain, 5e-9 m/(N s) on walls 1200 long, is 6e-6 m/(Pa s) on stress.
for wall in wall1_bottom wall3_top; do "$demctl" servo "$wall" 5e5 --gain 6e-6 --max-speed 50; done
for wall in wall2_right wall4_left; do "$demctl" servo "$wall" 2e5 --gain 6e-6 --max-speed 50; done
"$demctl" cycle 200000 --wait

step "loading: the top plate moves down at 0.2 units/s until it carries 1.5 MPa; the sides hold 200 kPa"
"$demctl" wall-velocity wall1_bottom 0 0
"$demctl" wall-velocity wall3_top 0 -0.2
# The monitor subscribes first, then the loading stage runs while it prints.
"$demctl" monitor --wall wall3_top --wall wall2_right --csv "$out/monitor.csv" 2>"$out/monitor.log" &
monitor_pid=$!
for _ in $(seq 200); do grep -q monitoring "$out/monitor.log" 2>/dev/null && break; sleep 0.05; done
sleep 0.5
"$demctl" --quiet run-until --wall wall3_top --stress 1.5e6 --max-cycles 200000 --check-interval 100 --wait
sleep 0.5
kill -INT "$monitor_pid"
wait "$monitor_pid"
monitor_pid=""

step "results"
"$demctl" status
"$demctl" contacts --csv "$out/contacts.csv" --limit 5
"$demctl" snapshot save "$out/final.snapshot"

step "stopping the server"
"$demctl" shutdown
for _ in $(seq 200); do kill -0 "$server_pid" 2>/dev/null || break; sleep 0.05; done
if kill -0 "$server_pid" 2>/dev/null; then
  echo "dem_server did not stop" >&2
  exit 1
fi
wait "$server_pid"
server_pid=""

echo
echo "Results in $out:"
echo "  monitor.csv        plate stress and settlement (top plate, right wall) and contact statistics, every 500 cycles"
echo "  contacts.csv       every contact at the end, as demctl received it"
echo "  final.snapshot     the whole state, for an exact restart (demctl snapshot load)"
echo "  verification_assembly/{walls,assembly,contacts,particles}.csv   the server's own tables"
echo "  dem_server.log     every command the server received, its reply and how long it took"
