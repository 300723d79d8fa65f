#!/usr/bin/env bash
# Today's dem_server and a ROS 2 node built from the package's first files
# (rosidl_older_node.c): the node reads the status and telemetry, its
# commands get no reply, and the server's log says why at discovery - the
# node's Command and Reply are of dem_interfaces 0.1.0, the fields they
# lack named - while its Status and PlateForces readers meet and are not
# reported.
#   rosidl_older_node.sh DEM_SERVER DEMCTL NODE CASE OUT DOMAIN
set -uo pipefail
dem_server="$1" demctl="$2" node="$3" case_file="$4" out="$5" domain="$6"
rm -rf "$out" && mkdir -p "$out"
"$dem_server" --name older --domain "$domain" --case "$case_file" --telemetry-cycles 10 --threads 1 \
  --out "$out" >"$out/dem_server.log" 2>&1 &
server=$!
trap 'kill -9 $server 2>/dev/null || true' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
d=("$demctl" --server older --domain "$domain" --timeout 10 --quiet)
"${d[@]}" cycle 100 --wait >"$out/cycle.log" 2>&1 || fail "cycle 100: $(cat "$out/cycle.log")"
"$node" "$domain" older || fail "the node's checks"
"${d[@]}" shutdown >"$out/shutdown.log" 2>&1 || fail "shutdown: $(cat "$out/shutdown.log")"
wait "$server" || fail "dem_server exited $?"
trap - EXIT
log="$out/dem_server.log"
warned() { grep -F "[warning]" "$log" | grep -qF -- "$1" || fail "the server's log lacks a warning: $1"; }
warned "rt/dem/older/command: a writer of Command built from dem_interfaces 0.1.0 as of 0308f76, whose Command lacks force, programme_steps, query.particle_set, query.particle: its samples cannot be read by this server (dem_interfaces 0.3.0) and are dropped; rebuild it from dem_interfaces 0.3.0"
warned "rt/dem/older/reply: a reader of Reply built from dem_interfaces 0.1.0 as of 0308f76 to 0ff9d3e"
if grep -E "rt/dem/older/(status|plate_forces):" "$log" | grep -q "built from"; then
  fail "the server reported the node's Status or PlateForces readers, which meet"
fi
echo "the server's log on the node:"
grep -F "built from" "$log" | sed 's/^/  /'
[ $failures -eq 0 ] && echo "all passed" || { echo "$failures failure(s)"; exit 1; }
