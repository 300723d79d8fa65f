#!/usr/bin/env bash
# Watching a sweep (docs/SWEEPS.md): `demctl servers --sweep NAME` lists the
# servers named NAME_<task> and no other; `demctl monitor --sweep NAME`
# follows each of them as it comes and goes, one table whose rows name
# their server, and ends with --idle-exit once they have all gone. A server
# of another name on the same domain is left out. On loopback.
#   demctl_monitor_sweep.sh DEM_SERVER DEMCTL CASES_DIR OUT_DIR DOMAIN
set -euo pipefail
server_program=$1 demctl=$2 cases=$3 out=$4 domain=$5
rm -rf "$out" && mkdir -p "$out"
pids=()
cleanup() { for pid in "${pids[@]}"; do kill -9 "$pid" 2>/dev/null || true; done; }
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  for log in "$out"/*.log "$out"/*.err; do [ -f "$log" ] && sed "s|^|  $(basename "$log") |" "$log" >&2; done
  exit 1
}

# Two servers of sweep "tsw" and one of another name, idle (no case yet).
for name in tsw_0000 tsw_0001 other; do
  "$server_program" --name "$name" --domain "$domain" --out "$out/$name" --threads 1 --telemetry-cycles 10 \
    --log-level warn >"$out/$name.log" 2>&1 &
  pids+=($!)
done
dc=("$demctl" --domain "$domain" --timeout 10)
for name in tsw_0000 tsw_0001 other; do "${dc[@]}" --server "$name" status >/dev/null || fail "$name did not start"; done

"${dc[@]}" servers --sweep tsw >"$out/servers.txt"
grep -q "^tsw_0000 " "$out/servers.txt" && grep -q "^tsw_0001 " "$out/servers.txt" ||
  fail "servers --sweep tsw does not list both servers: $(cat "$out/servers.txt")"
! grep -q "^other " "$out/servers.txt" || fail "servers --sweep tsw lists the server named other"
echo "ok: servers --sweep lists the sweep's two servers only"

code=0
"${dc[@]}" monitor --idle-exit 2 >/dev/null 2>"$out/bad.err" || code=$?
[ "$code" -eq 2 ] || fail "monitor --idle-exit without --sweep exited $code, expected 2"

"${dc[@]}" monitor --sweep tsw --idle-exit 2 --csv "$out/sweep.csv" >"$out/monitor.out" 2>"$out/monitor.err" &
monitor=$!
pids+=($monitor)
for _ in $(seq 100); do grep -q "following server tsw_0001" "$out/monitor.err" 2>/dev/null && break; sleep 0.1; done
grep -q "following server tsw_0000" "$out/monitor.err" || fail "the monitor did not find tsw_0000"

# Each runs the nine discs for a while; so does the other one.
for name in tsw_0000 tsw_0001 other; do
  "${dc[@]}" --server "$name" load "$cases/ball/nine_disc_damped.case.txtpb" >/dev/null
  "${dc[@]}" --server "$name" wall-velocity top 0 -0.5 >/dev/null
  "${dc[@]}" --server "$name" cycle 300 --wait --quiet >/dev/null
done
for name in tsw_0000 tsw_0001 other; do "${dc[@]}" --server "$name" shutdown >/dev/null; done

# The monitor ends by itself 2 s after the last of the sweep left.
for _ in $(seq 150); do kill -0 "$monitor" 2>/dev/null || break; sleep 0.1; done
kill -0 "$monitor" 2>/dev/null && fail "the monitor did not end after the sweep's servers left"
wait "$monitor" || fail "the monitor exited $?"
echo "ok: monitor --sweep ended by itself after the servers left"

head -1 "$out/sweep.csv" | grep -q "^server,cycle,time,bottom_stress,bottom_settlement," || fail "sweep.csv's header"
for name in tsw_0000 tsw_0001; do
  rows=$(grep -c "^$name," "$out/sweep.csv" || true)
  [ "$rows" -ge 20 ] || fail "sweep.csv has $rows rows of $name, expected about 30 (300 cycles, every 10)"
  grep -q "server $name left: shutdown" "$out/monitor.err" || fail "the monitor did not say $name left"
  echo "ok: $rows rows of $name"
done
! grep -q "^other," "$out/sweep.csv" || fail "sweep.csv has rows of the server named other"
grep -q "^server  *cycle" "$out/monitor.out" || fail "the table has no server column"
echo "ok: the other server's telemetry is left out"
