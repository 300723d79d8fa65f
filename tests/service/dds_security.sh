#!/usr/bin/env bash
# DDS Security (docs/SECURITY.md): a dem_server whose configuration
# requires authentication, access control and encryption answers a client
# with an identity from the same CA and permissions, and nobody else - a
# participant without security, or one whose certificate another CA signed,
# finds no server: it can neither command it nor read its telemetry. And
# (where packets can be captured: root) no packet on the loopback carries
# the server's name - its topics' names - in clear text: discovery and
# liveliness are protected too.
#   dds_security.sh DEM_SERVER DEMCTL CASES_DIR WORK_DIR DOMAIN
set -uo pipefail
server_program=$1 demctl=$2 cases=$3 work=$4 domain=$5
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
server=""
sniffer=""
trap '[ -n "$server" ] && kill -9 "$server" 2>/dev/null; [ -n "$sniffer" ] && kill "$sniffer" 2>/dev/null' EXIT
# A name no other test's traffic on the machine holds.
name="secure_$(printf '%x' "$$")x$domain"

ca=$(bash "$root/scripts/make_test_ca.sh" "$work/ca" server client) || { echo "FAIL: make_test_ca.sh"; exit 1; }
/usr/bin/python3 "$root/tests/service/rtps_sniff.py" 20 "$name" >"$work/sniff.out" 2>&1 &
sniffer=$!
"$server_program" --name "$name" --domain "$domain" --dds-config "file://$ca/cyclonedds-server.xml" \
  --out "$work/server" --threads 1 --telemetry-cycles 10 >"$work/server.log" 2>&1 &
server=$!

as() {  # WHO COMMAND...: demctl with WHO's configuration (none: the plain loopback one)
  local who=$1
  shift
  local config="file://$root/config/cyclonedds-loopback.xml"
  [ "$who" = none ] || config="file://$ca/cyclonedds-$who.xml"
  CYCLONEDDS_URI="$config" timeout 60 "$demctl" --server "$name" --domain "$domain" "$@"
}
expect() {  # CODE WHAT WHO COMMAND...
  local want=$1 what=$2
  shift 2
  as "$@" >"$work/last.out" 2>&1
  local got=$?
  if [ "$got" -ne "$want" ]; then
    fail "$what: exit $got, expected $want"
    sed 's/^/  | /' "$work/last.out"
  else
    echo "ok: $what"
  fi
}

expect 0 "the authorised client reads the status" client --timeout 15 status
expect 0 "and loads a case" client --timeout 15 load "$cases/ball/nine_disc_damped.case.txtpb"
expect 0 "and cycles" client --timeout 15 cycle 200 --wait
expect 0 "starts a long run" client --timeout 15 cycle 100000000
expect 0 "and reads its telemetry" client --timeout 15 monitor --samples 2
wait "$sniffer"
sniffed=$?
sniffer=""
if [ "$sniffed" -eq 2 ]; then
  echo "skipped: the look at the packets ($(head -n 1 "$work/sniff.out"))"
elif ! grep -q '^clear 0$' "$work/sniff.out" || grep -q '^packets 0$' "$work/sniff.out"; then
  fail "the server's name in clear text on the loopback: $(tr '\n' ' ' <"$work/sniff.out")"
else
  echo "ok: none of $(sed -n 's/^packets //p' "$work/sniff.out") RTPS packets on the loopback carries the server's name in clear"
fi

for who in none intruder; do
  label=$([ "$who" = none ] && echo "a client without security" || echo "a client of another CA")
  expect 3 "$label finds no server to command" "$who" --timeout 3 shutdown
  expect 3 "$label reads no status" "$who" --timeout 3 status
  expect 3 "$label reads no telemetry" "$who" --timeout 3 monitor --samples 1
  # Nor does it see the server's topics at all.
  as "$who" --timeout 3 servers >"$work/last.out" 2>&1
  if grep -q "$name" "$work/last.out"; then fail "$label lists the server"; else echo "ok: $label lists no server"; fi
done

expect 0 "the server served on, untouched" client --timeout 15 status
grep -q "state      running" "$work/last.out" || fail "the run was stopped: $(cat "$work/last.out")"
expect 0 "the authorised client shuts it down" client --timeout 15 shutdown --force
wait "$server"
code=$?
server=""
[ "$code" -eq 0 ] || fail "dem_server exited $code"
[ "$failures" -eq 0 ] && echo PASS || { echo "$failures failures"; tail -n 20 "$work/server.log"; exit 1; }
