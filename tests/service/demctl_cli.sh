#!/usr/bin/env bash
# demctl as a user runs it, against a dem_server process on loopback: each
# subcommand's normal path, the distinct exit codes of its failures, and a
# clean stop by command and by SIGTERM.
#   demctl_cli.sh DEM_SERVER DEMCTL CASES_DIR OUT_DIR DOMAIN  (uses DOMAIN and DOMAIN + 1)
set -uo pipefail
server_program=$1 demctl=$2 cases=$3 out=$4 domain=$5
rm -rf "$out" && mkdir -p "$out"
server=""
monitor=""
cleanup() {
  for pid in $server $monitor; do kill -9 "$pid" 2>/dev/null; done
}
trap cleanup EXIT

source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
# wait_for PID SECONDS: its exit code, or 124 when it did not end in time.
wait_for() {
  local pid=$1 ticks=$(($2 * 10))
  while kill -0 "$pid" 2>/dev/null && [ $ticks -gt 0 ]; do sleep 0.1; ticks=$((ticks - 1)); done
  if kill -0 "$pid" 2>/dev/null; then return 124; fi
  wait "$pid"
}

"$server_program" --name cli --domain "$domain" --out "$out/server" --threads 1 --telemetry-cycles 20 \
  >"$out/server.log" 2>&1 &
server=$!
d=("$demctl" --server cli --domain "$domain" --timeout 10)

expect 3 "no such server" "$demctl" --server nobody --domain "$domain" --timeout 1 status
said 'no server "nobody" on DDS domain'
expect 2 "a missing argument" "${d[@]}" cycle
expect 2 "a negative cycle count" "${d[@]}" cycle -- -5
expect 2 "too few velocity components" "${d[@]}" wall-velocity top 1
expect 2 "a value that is not a number" "${d[@]}" set global_damping fast
expect 2 "run-until without a condition" "${d[@]}" run-until --max-cycles 5
expect 2 "a server name that is not a name" "$demctl" --server "a b" --domain "$domain" status

expect 0 "load" "${d[@]}" load "$cases/ball/nine_disc_damped.case.txtpb"
said "loaded case nine_disc_damped"
expect 0 "servers" "$demctl" --domain "$domain" servers
said "cli"
expect 4 "an unknown wall" "${d[@]}" wall-velocity roof 0 -1
said 'not_found: no wall "roof" (walls: bottom, right, top, left)'
printf 'material { name: "x" }\nwall { name: "w" h1: 1 h2: 1 material: "x" }\n' >"$out/broken.case.txtpb"
expect 4 "an invalid case" "${d[@]}" load "$out/broken.case.txtpb"
said "broken.case.txtpb:2:"
said "wall[0].h2: must be greater than h1"
expect 0 "wall-velocity" "${d[@]}" wall-velocity top 0 -12

# A monitor records five rows while a cycle runs.
"${d[@]}" monitor --samples 5 --csv "$out/monitor.csv" >"$out/monitor.out" 2>"$out/monitor.err" &
monitor=$!
for _ in $(seq 100); do grep -q monitoring "$out/monitor.err" && break; sleep 0.1; done
sleep 0.5
expect 0 "cycle --wait" "${d[@]}" cycle 200 --wait
said "ran 200 cycles to cycle 200"
wait_for "$monitor" 20
code=$?
monitor=""
[ "$code" -eq 0 ] || { cp "$out/monitor.err" "$out/last.err"; : >"$out/last.out"; fail "monitor: exit code $code"; }
rows=$(($(wc -l <"$out/monitor.csv") - 1))
[ "$rows" -eq 5 ] || fail "monitor.csv has $rows rows, expected 5"
head -1 "$out/monitor.csv" | grep -q "^cycle,time,bottom_stress,bottom_settlement," || fail "monitor.csv header"
grep -q "stress \[Pa\] settlement \[m\]" "$out/monitor.out" || fail "the monitor's table has no stress and settlement columns"

expect 0 "the wall stops" "${d[@]}" wall-velocity top 0 0
expect 0 "cycle (accepted at once)" "${d[@]}" cycle 1000000000
said "accepted: cycle of up to 1000000000 cycles"
expect 0 "status while running" "${d[@]}" status
said "state      running"
expect 0 "stop" "${d[@]}" stop
said "stopped cycle at cycle"
expect 0 "contacts" "${d[@]}" contacts --csv "$out/contacts.csv" --wall top
said "contacts at cycle"
head -1 "$out/contacts.csv" | grep -q "^first,second_kind,second,x,y,z," || fail "contacts.csv header"
grep -q ",wall,top," "$out/contacts.csv" || fail "contacts.csv names the wall"
# A condition never met: the cap ends the run, and the exit code says so.
expect 6 "run-until at its cap" "${d[@]}" run-until --wall top --settlement 1e9 --max-cycles 50 --wait
said "ran 50 cycles"
said "the cycle cap (50 cycles) came before the condition"
expect 0 "run-until meeting its condition" "${d[@]}" run-until --kinetic-energy 1e30 --max-cycles 50 --wait
said "after 1 cycles"
expect 0 "status --json" "${d[@]}" status --json
/usr/bin/python3 -c "import json, sys; s = json.load(open(sys.argv[1])); assert s['status']['server'] == 'cli'" \
  "$out/last.out" || fail "status --json is not JSON naming the server"
expect 0 "snapshot save" "${d[@]}" snapshot save "$out/state.snapshot"
[ -s "$out/state.snapshot" ] || fail "no snapshot file"
expect 0 "snapshot save --on-server" "${d[@]}" snapshot save kept.snapshot --on-server
[ -s "$out/server/kept.snapshot" ] || fail "no snapshot in the server's output directory"
expect 0 "snapshot load" "${d[@]}" snapshot load "$out/state.snapshot"
said "loaded snapshot of nine_disc_damped"
expect 4 "a garbage snapshot" "${d[@]}" snapshot load "$out/broken.case.txtpb"
said "not a dem snapshot"
expect 0 "set" "${d[@]}" set friction.disc 0.4
said "friction of disc set to 0.4"
expect 0 "set gravity" "${d[@]}" set gravity 0,-9.81
expect 4 "an unknown parameter" "${d[@]}" set stiffness 1
expect 0 "servo" "${d[@]}" servo top 1e6
said "servo-controlled to 1e+06 Pa"
expect 0 "shutdown" "${d[@]}" shutdown
said "server cli stopped"
wait_for "$server" 20
code=$?
server=""
[ "$code" -eq 0 ] || fail "dem_server exit code $code after shutdown"
[ -s "$out/server/nine_disc_damped/walls.csv" ] || fail "the server wrote no walls.csv"

# SIGTERM: a clean exit too.
"$server_program" --name term --domain $((domain + 1)) --out "$out/term" >"$out/term.log" 2>&1 &
server=$!
expect 0 "a second server comes up" "$demctl" --server term --domain $((domain + 1)) --timeout 10 status
kill -TERM "$server"
wait_for "$server" 20
code=$?
server=""
[ "$code" -eq 0 ] || fail "dem_server exit code $code after SIGTERM"

echo "$failures failures"
[ "$failures" -eq 0 ]
