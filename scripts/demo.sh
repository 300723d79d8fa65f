#!/usr/bin/env bash
# The main job: Miyata et al.'s (2002) uniaxial compression test through the
# simulation service. Builds the project, starts dem_server on loopback in
# one-shot mode with the case CS of Table 1 (circular particles, smooth
# surface; cases/miyata/cs.case.txtpb): it generates the sample, lets it
# settle under gravity, trims it at 2.7 m, settles it again, places the
# loading plate on top and lowers it at 0.01 m/s until it carries 900 kPa.
# Meanwhile `demctl monitor` shows the loading plate's stress against its
# settlement live, and records it, `demctl record` keeps the telemetry as a
# ROS 2 bag (MCAP), and the bridge (python3 -m dem.bridge) serves a live
# dashboard page and the Foxglove WebSocket protocol; at the end the curve
# is drawn as a PNG, and ParaView (pvpython, headless) draws the compressed
# sample with its force chains from the server's ParaView files.
# It installs and builds only what it runs (scripts/build.sh --for demo:
# dem_server, demctl, the Python client; pvpython) and prints how long
# each part took.
# Outputs go to out/demo/ (or the directory given as $1). Another case:
#   DEM_DEMO_CASE=cases/miyata/ss_reduced.case.txtpb bash scripts/demo.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/lib/timing.sh"
out="$(mkdir -p "${1:-$root/out}/demo" && cd "${1:-$root/out}/demo" && pwd)"
case_file="$(realpath "${DEM_DEMO_CASE:-$root/cases/miyata/cs.case.txtpb}")"
demo_start=$(clock)
parts=()
# A part's name and how long it took, for the summary at the end.
took() { parts+=("$(printf '  %-44s %s' "$1" "$(since "$2")")"); }

printf '== the packages and the build: dem_server, demctl, the Python client\n'
start=$(clock)
bash "$root/scripts/build.sh" --for demo
took "packages and build" "$start"

# Loopback only: 127.0.0.1, multicast off, peers on localhost.
export CYCLONEDDS_URI="file://$root/config/cyclonedds-loopback.xml"
export DEM_SERVER=demo DEM_DOMAIN="${DEM_DEMO_DOMAIN:-30}"
demctl="$root/build/clients/cpp/demctl/demctl"
server_pid=""
bridge_pid=""
record_pid=""
cleanup() {
  for pid in "$server_pid" "$record_pid" "$bridge_pid"; do
    if [[ -n "$pid" ]]; then kill "$pid" 2>/dev/null || true; fi
  done
}
trap cleanup EXIT
step() { printf '\n== %s\n' "$*"; }

rm -rf "$out" && mkdir -p "$out"
start=$(clock)
step "the live dashboard: python3 -m dem.bridge on DDS domain $DEM_DOMAIN (log: $out/bridge.log)"
# Port 0: any free port; the bridge prints the one it got.
PYTHONPATH="$root/build/clients/python" /usr/bin/python3 -m dem.bridge --domain "$DEM_DOMAIN" \
  --port "${DEM_DEMO_BRIDGE_PORT:-0}" >"$out/bridge.log" 2>&1 &
bridge_pid=$!
for _ in $(seq 100); do grep -q "dashboard http" "$out/bridge.log" && break; sleep 0.1; done
grep -q "dashboard http" "$out/bridge.log" || { echo "the bridge did not start; its log:" >&2; cat "$out/bridge.log" >&2; exit 1; }
echo "  open $(grep -o 'http://[^ ]*' "$out/bridge.log") in a browser while the run goes on (Foxglove:" \
  "$(grep -o 'ws://[^ ]*' "$out/bridge.log"))"

step "starting dem_server \"$DEM_SERVER\" on DDS domain $DEM_DOMAIN with $(basename "$case_file") (log: $out/dem_server.log)"
"$root/build/service/dem_server" --name "$DEM_SERVER" --domain "$DEM_DOMAIN" --out "$out" \
  --case "$case_file" --run-and-exit --telemetry-cycles 1000 --vtk-interval 10000 >"$out/dem_server.log" 2>&1 &
server_pid=$!
"$demctl" --timeout 30 record "$out/telemetry.mcap" >"$out/record.log" 2>&1 &
record_pid=$!

step "demctl monitor: the loading plate (top) and the bottom plate, live, until the server is done"
# Zero stress on the top plate while the sample is prepared; its settlement
# counts from where the plate is placed on the sample.
"$demctl" --timeout 30 monitor --wall top --wall bottom --csv "$out/monitor.csv"

if ! wait "$server_pid"; then
  server_pid=""
  echo "dem_server failed; its log:" >&2
  tail -20 "$out/dem_server.log" >&2
  exit 1
fi
server_pid=""
wait "$record_pid" || { echo "demctl record failed; its log:" >&2; cat "$out/record.log" >&2; exit 1; }
record_pid=""
kill "$bridge_pid" && wait "$bridge_pid" || true
bridge_pid=""
grep -E "stage|programme" "$out/dem_server.log" | sed 's/^\[[^]]*\] \[[^]]*\] \[[^]]*\] /  /'
took "the run (dem_server, monitor, record, dashboard)" "$start"

step "the stress-settlement curve"
start=$(clock)
PYTHONPATH="$root/build/clients/python" /usr/bin/python3 -m dem.plots stress-settlement \
  "$out/monitor.csv" "$out/stress_settlement.png" --wall top \
  --title "$(basename "$case_file" .case.txtpb): loading plate stress against settlement"

took "the stress-settlement curve (matplotlib)" "$start"

step "the force chains at the end (ParaView, headless)"
start=$(clock)
case_out="$(dirname "$(ls "$out"/*/particles.pvd | head -1)")"
bash "$root/scripts/pvpython.sh" "$root/tools/paraview/force_chains.py" "$case_out" "$out/force_chains.png" \
  --title "$(basename "$case_file" .case.txtpb): contact normal forces at the end of loading" 2>"$out/pvpython.log" ||
  { echo "pvpython failed; its log:" >&2; tail -20 "$out/pvpython.log" >&2; exit 1; }
took "the force chains (ParaView)" "$start"

echo
echo "Results in $out:"
echo "  monitor.csv             the live table: plate stress and settlement, contact statistics, every 1000 cycles"
echo "  stress_settlement.png   the loading plate's stress against its settlement (Miyata Fig. 26)"
echo "  force_chains.png        the sample at the end with its contact forces (ParaView)"
echo "  telemetry.mcap          the run's telemetry as a ROS 2 bag (Foxglove; python3 -m dem.plots stress-settlement)"
echo "  */particles.pvd, contacts.pvd, walls.pvd   ParaView time series every 10,000 cycles (open in paraview)"
echo "  */walls.csv, assembly.csv, stages.csv, contacts.csv, particles.csv   the server's own tables"
echo "  */compression*.csv, plate_contacts.csv, force_distribution.csv, force_tail.csv, load_by_state.csv,"
echo "    stress_drops.csv      the plate loading analyses (Miyata Figs. 26-37; docs/CASES.md)"
echo "  */final.snapshot        the whole final state, for an exact restart (demctl snapshot load)"
echo "  dem_server.log          the server's log"

echo
echo "How long each part took:"
printf '%s\n' "${parts[@]}"
printf '  %-44s %s\n' "the whole demo" "$(since "$demo_start")"
