#!/usr/bin/env bash
# dem_server under an address-space cap (ulimit -v; issue 37, docs/RELIABILITY.md,
# "Memory"): the memory budget follows the cap, and a cycle that runs out of
# memory is a failed reply and the last good state, never the server's end.
#   memory_cap.sh DEM_SERVER DEMCTL DATA_DIR CASES_DIR OUT_DIR DOMAIN
# The cap (1,150,000 kB) was set from what dem_server --threads 1 maps:
# about 500 MB started, 870 MB with the 200,000-sphere lattice loaded (915
# at the load's peak), 1,420 MB at its first cycle's peak.
set -uo pipefail
server_program=$1 demctl=$2 data=$3 cases=$4 out=$5 domain=$6
cap_kb=1150000
rm -rf "$out" && mkdir -p "$out"
server=""
cleanup() { [ -n "$server" ] && kill -9 "$server" 2>/dev/null; }
trap cleanup EXIT

source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
# start NAME [OPTIONS...]: a dem_server under the cap, its pid in $server.
start() {
  local name=$1
  shift
  (ulimit -v "$cap_kb" && exec "$server_program" --name "$name" --domain "$domain" --out "$out/$name" --threads 1 \
    "$@") >"$out/$name.log" 2>&1 &
  server=$!
}
# stop: shuts the server down and checks it ended by itself, exit code 0.
stop() {
  expect 0 "shutdown" "${d[@]}" shutdown
  local ticks=100
  while kill -0 "$server" 2>/dev/null && [ $ticks -gt 0 ]; do sleep 0.1; ticks=$((ticks - 1)); done
  if kill -0 "$server" 2>/dev/null; then
    fail "the server did not end after shutdown"
  else
    wait "$server"
    local code=$?
    [ "$code" -eq 0 ] || fail "the server exited with $code"
  fi
  server=""
}
vm_peak() { grep -E '^VmPeak' "/proc/$server/status" | awk '{print $2}'; }
# ran_out: the last reply said memory ran out, naming the cap, and the server lives on.
ran_out() {
  said "memory ran out (std::bad_alloc"
  said "ulimit -v $cap_kb"
  echo "  reply: $(cat "$out/last.err")"
  kill -0 "$server" 2>/dev/null || fail "the server ended"
}
# answers STATE: get_state answers, the world in STATE at cycle 0.
answers() {
  expect 0 "get_state answers" "${d[@]}" status --json
  said "\"state_name\":\"$1\""
  said '"cycle":0,'
}

# The budget is half of what the cap leaves (about 550 MB: 225,000 particles
# at 2.5 kB): the lattice of twice as many layers is refused at load, naming the cap.
sed 's/layers: 20/layers: 40/' "$data/memory_cap.case.txtpb" >"$out/memory_cap_400k.case.txtpb"
start budget
d=("$demctl" --server budget --domain "$domain" --timeout 20 -q)
expect 4 "400,000 spheres refused by the budget under the cap" "${d[@]}" load "$out/memory_cap_400k.case.txtpb"
said "more than the particle budget"
said "ulimit -v $cap_kb"
echo "  refused: $(cat "$out/last.err")"
stop

# 200,000 spheres are within the budget: the lattice loads, and its first
# cycle runs out of memory (the budget counts neither what DDS maps after
# the start nor a contact search's address space).
start oom
d=("$demctl" --server oom --domain "$domain" --timeout 20 -q)
expect 0 "the lattice loads under the cap" "${d[@]}" load "$data/memory_cap.case.txtpb"
echo "  address space at its peak after the load: $(vm_peak) kB of $cap_kb"
expect 4 "its first cycle fails" "${d[@]}" cycle --wait 1
said "failed: the run failed at cycle"
said "the world is back at the last good state, cycle 0"
ran_out
answers error
expect 0 "its status says why" "${d[@]}" status
said "memory ran out"
# Saving it needs its bytes beside the world: under the cap that may run out too, a failed reply then.
"${d[@]}" snapshot save "$out/last_good.snapshot" >"$out/last.out" 2>"$out/last.err"
code=$?
case $code in
  0) echo "ok: the last good state is saved" ;;
  4) echo "ok: saving the last good state ran out of memory: a failed reply" && ran_out ;;
  *) fail "snapshot save: exit code $code" ;;
esac
# A programme of it: its start (a copy of the world, the last good state)
# already runs out, a failed reply with nothing started.
expect 0 "the lattice loads again" "${d[@]}" load "$data/memory_cap.case.txtpb"
expect 4 "its programme fails" "${d[@]}" run-programme --wait
ran_out
answers loaded
expect 0 "a small case loads" "${d[@]}" load "$cases/ball/nine_disc_damped.case.txtpb"
expect 0 "and runs" "${d[@]}" cycle --wait 100
said "ran 100 cycles to cycle 100"
echo "  address space at its peak: $(vm_peak) kB of $cap_kb"
stop

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s); the servers' logs are in $out"
  exit 1
fi
echo "dem_server under ulimit -v $cap_kb: refused by the budget, then a cycle out of memory failed and the server served on"
