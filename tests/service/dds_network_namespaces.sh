#!/usr/bin/env bash
# DDS across hosts (docs/DDS.md, "Across hosts"): two network namespaces
# made here stand for two hosts, joined by a veth pair with addresses
# assigned here (10.216.0.1 and 10.216.0.2; no other address is used), each
# with the configuration scripts/dds_network_config.sh writes for its side
# (its veth interface, unicast peers, no multicast). Host A runs a server and
# the two tasks of a sweep; from host B, demctl finds them all (servers,
# servers --sweep), commands the server (load, wall-velocity, cycle,
# status), follows its telemetry (monitor) and the sweep's (monitor
# --sweep), and moves snapshots both ways (save and load, transferred over
# DDS). Needs root (ip netns); exits 77 (a skip) otherwise.
#   dds_network_namespaces.sh SOURCE_DIR DEM_SERVER DEMCTL OUT_DIR DOMAIN
set -euo pipefail
source_dir=$1 server_program=$2 demctl=$3 out=$4 domain=$5
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: network namespaces need root"
  exit 77
fi
rm -rf "$out" && mkdir -p "$out"
# Names of this run only, so runs side by side or left behind never meet.
tag=$$
ns_a="dem-a-$tag" ns_b="dem-b-$tag" veth_a="dema$tag" veth_b="demb$tag"
address_a=10.216.0.1 address_b=10.216.0.2
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -9 "$pid" 2>/dev/null || true; done
  # $! is the subshell of on_a/on_b, not what `ip netns exec` started in it:
  # everything still running inside the namespaces goes too, or a server
  # left behind keeps the test's file descriptors open (a caller's lock).
  for ns in "$ns_a" "$ns_b"; do
    for pid in $(ip netns pids "$ns" 2>/dev/null); do kill -9 "$pid" 2>/dev/null || true; done
  done
  ip netns del "$ns_a" 2>/dev/null || true  # takes the veth pair with it
  ip netns del "$ns_b" 2>/dev/null || true
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  for log in "$out"/*.log "$out"/*.err; do [ -f "$log" ] && tail -8 "$log" | sed "s|^|  $(basename "$log") |" >&2; done
  exit 1
}

ip netns add "$ns_a"
ip netns add "$ns_b"
ip link add "$veth_a" type veth peer name "$veth_b"
ip link set "$veth_a" netns "$ns_a"
ip link set "$veth_b" netns "$ns_b"
ip -n "$ns_a" addr add "$address_a/24" dev "$veth_a"
ip -n "$ns_b" addr add "$address_b/24" dev "$veth_b"
for ns in "$ns_a" "$ns_b"; do ip -n "$ns" link set lo up; done
ip -n "$ns_a" link set "$veth_a" up
ip -n "$ns_b" link set "$veth_b" up
for _ in $(seq 50); do ip -n "$ns_b" -br link show "$veth_b" | grep -q LOWER_UP && break; sleep 0.1; done
ip -n "$ns_b" -br link show "$veth_b" | grep -q LOWER_UP || fail "the veth pair is not up"
echo "ok: namespaces $ns_a ($address_a) and $ns_b ($address_b) joined by a veth pair"

config="$source_dir/scripts/dds_network_config.sh"
bash "$config" --interface "$veth_a" --peer "$address_a" --peer "$address_b" >"$out/cyclonedds-a.xml"
bash "$config" --interface "$veth_b" --peer "$address_a" --peer "$address_b" >"$out/cyclonedds-b.xml"
on_a() { ip netns exec "$ns_a" env CYCLONEDDS_URI="file://$out/cyclonedds-a.xml" "$@"; }
on_b() { ip netns exec "$ns_b" env CYCLONEDDS_URI="file://$out/cyclonedds-b.xml" "$@"; }
dc=("$demctl" --domain "$domain" --timeout 20)

# Host A: a server to drive.
# It reads cases from the repository and the shared packings beside it
# (a server reads only the directories it is given: RELIABILITY.md).
on_a "$server_program" --name press --domain "$domain" --out "$out/press" --threads 1 --telemetry-cycles 10 \
  --read-dir "$source_dir/cases" --read-dir "$source_dir/../shared/bench" >"$out/press.log" 2>&1 &
pids+=($!)

# Host B: discovery, then commands.
on_b "${dc[@]}" --server press status >"$out/status.log" 2>&1 || fail "host B cannot reach the server on host A"
on_b "${dc[@]}" servers >"$out/servers.log" 2>&1
grep -q "^press " "$out/servers.log" || fail "demctl servers on host B does not list press"
echo "ok: discovery: host B lists and reaches the server on host A"
on_b "${dc[@]}" --server press load "$source_dir/cases/ball/nine_disc_damped.case.txtpb" >"$out/load.log" 2>&1 ||
  fail "load from host B"
on_b "${dc[@]}" --server press wall-velocity top 0 -0.5 >/dev/null || fail "wall-velocity from host B"

# Telemetry to host B while a run goes on.
on_b "${dc[@]}" --server press monitor --samples 20 --csv "$out/monitor.csv" >"$out/monitor.log" 2>"$out/monitor.err" &
monitor=$!
pids+=($monitor)
for _ in $(seq 100); do grep -q monitoring "$out/monitor.err" 2>/dev/null && break; sleep 0.1; done
sleep 1  # the monitor's readers matched across the link
on_b "${dc[@]}" --server press cycle 400 --wait --quiet >"$out/cycle.log" 2>&1 || fail "cycle from host B"
for _ in $(seq 100); do kill -0 "$monitor" 2>/dev/null || break; sleep 0.1; done
wait "$monitor" || fail "the monitor on host B exited $?"
rows=$(($(wc -l <"$out/monitor.csv") - 1))
[ "$rows" -eq 20 ] || fail "the monitor on host B recorded $rows rows, expected 20"
echo "ok: commands from host B ran 400 cycles on host A; its monitor recorded 20 rows of telemetry"

# Snapshots both ways: saved on host A and transferred to host B byte for byte the same;
# then loaded back from host B's copy, the state as it was.
on_b "${dc[@]}" --server press snapshot save --on-server here.snapshot >/dev/null || fail "snapshot save on the server"
on_b "${dc[@]}" --server press snapshot save "$out/there.snapshot" >/dev/null || fail "snapshot transfer to host B"
cmp -s "$out/press/here.snapshot" "$out/there.snapshot" || fail "the transferred snapshot differs from the server's"
hash_of() { on_b "${dc[@]}" --server press status --json | sed -n 's/.*"state_hash": *\([0-9]*\).*/\1/p'; }
saved=$(hash_of)
on_b "${dc[@]}" --server press cycle 100 --wait --quiet >/dev/null || fail "cycle after the save"
[ "$(hash_of)" != "$saved" ] || fail "100 more cycles did not change the state"
on_b "${dc[@]}" --server press snapshot load "$out/there.snapshot" >/dev/null || fail "snapshot transfer to host A"
[ "$(hash_of)" = "$saved" ] || fail "the snapshot sent back from host B did not restore the state"
echo "ok: snapshots: $(stat -c %s "$out/there.snapshot") bytes to host B identical to the server's file; sent back, the state hash is the saved one"
# A large one: the dense benchmark's 10,000 spheres (about 18 MB, in chunks of 1 MiB, each in UDP fragments).
bench="$source_dir/cases/bench/plate_compression_10k.case.txtpb"
on_b "${dc[@]}" --server press load --on-server "$bench" >/dev/null || fail "loading the 10k bed"
started=$(date +%s%N)
on_b "${dc[@]}" --server press snapshot save "$out/bed.snapshot" >/dev/null || fail "the 10k bed's snapshot to host B"
milliseconds=$((($(date +%s%N) - started) / 1000000))
on_b "${dc[@]}" --server press snapshot save --on-server bed.snapshot >/dev/null || fail "the 10k bed's snapshot on A"
cmp -s "$out/press/bed.snapshot" "$out/bed.snapshot" || fail "the 10k bed's snapshot differs on host B"
echo "ok: the 10k bed's snapshot, $(stat -c %s "$out/bed.snapshot") bytes, to host B in $milliseconds ms, identical"

# A sweep of two tasks on host A (slow plates, so both run a while), watched from host B by name.
sweep="$out/sweep"
/usr/bin/python3 - "$sweep" "$domain" "file://$out/cyclonedds-a.xml" <<'PY'
import sys
import dem, dem.sweep
dem.sweep.Sweep.create(sys.argv[1], dem.paths.cases_dir() / "miyata" / "cs_reduced.case.txtpb",
                       {"material[*].friction": [0.3, 0.6], "stage[2].wall[0].motion.velocity.y": [-0.01]},
                       name="net", domain=int(sys.argv[2]), dds_config=sys.argv[3])
PY
on_b "${dc[@]}" monitor --sweep net --idle-exit 4 --csv "$out/sweep_monitor.csv" >"$out/sweep_monitor.log" \
  2>"$out/sweep_monitor.err" &
sweep_monitor=$!
pids+=($sweep_monitor)
on_a /usr/bin/python3 -m dem.sweep run "$sweep" --backend local --workers 2 --poll 0.5 >"$out/sweep.log" 2>&1 &
sweep_run=$!
pids+=($sweep_run)
listed=""
for _ in $(seq 100); do
  on_b "${dc[@]}" servers --sweep net --wait 1 >"$out/sweep_servers.log" 2>&1 || true
  if grep -q "^net_0000 " "$out/sweep_servers.log" && grep -q "^net_0001 " "$out/sweep_servers.log"; then
    listed=yes
    break
  fi
  kill -0 "$sweep_run" 2>/dev/null || break
done
[ -n "$listed" ] || fail "demctl servers --sweep net on host B never listed both tasks' servers"
! grep -q "^press " "$out/sweep_servers.log" || fail "servers --sweep net lists press"
wait "$sweep_run" || fail "the sweep on host A exited $?"
for _ in $(seq 150); do kill -0 "$sweep_monitor" 2>/dev/null || break; sleep 0.1; done
wait "$sweep_monitor" || fail "the sweep's monitor on host B exited $?"
for server in net_0000 net_0001; do
  rows=$(grep -c "^$server," "$out/sweep_monitor.csv" || true)
  [ "$rows" -ge 10 ] || fail "host B's monitor --sweep recorded $rows rows of $server"
done
echo "ok: a sweep's two servers on host A listed by name from host B, and followed there by monitor --sweep"

on_b "${dc[@]}" --server press shutdown >/dev/null || fail "shutdown from host B"
wait "${pids[0]}" || fail "the server on host A exited $?"
echo "ok: shut down from host B"
