#!/usr/bin/env bash
# The discovery probe against a running dem_server (docs/RELIABILITY.md,
# "Discovery"): the server, cycling a case and publishing telemetry, meets
# ROUNDS rounds of peers describing its type names otherwise, type-lookup
# requests and damaged discovery messages; it must be alive after each,
# still answer, and shut down cleanly with nothing reported by a
# sanitizer. The issue's thousand rounds under ASan: ROUNDS=1000 with an
# ASan build's dem_server (docs/RELIABILITY.md says how). Options after
# ROUNDS go to the probe (--no-peers: the hand-made messages alone, which
# grow discovery past 256 endpoints within some 140 rounds).
#   discovery_probe.sh DEM_SERVER DEMCTL PROBE CASES_DIR WORK_DIR DOMAIN ROUNDS [PROBE_OPTIONS...]
set -uo pipefail
server_program=$1 demctl=$2 probe=$3 cases=$4 work=$5 domain=$6 rounds=$7
shift 7
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
server=""
trap '[ -n "$server" ] && kill -9 "$server" 2>/dev/null' EXIT

"$server_program" --name probed --domain "$domain" --out "$work/server" --threads 1 --telemetry-cycles 10 \
  --case "$cases/ball/nine_disc_damped.case.txtpb" >"$work/server.log" 2>&1 &
server=$!
ctl() { timeout 60 "$demctl" --server probed --domain "$domain" --timeout 15 "$@"; }
ctl cycle 100000000 >"$work/cycle.out" 2>&1 || fail "starting a run: $(cat "$work/cycle.out")"

"$probe" --domain "$domain" --server probed --server-pid "$server" --rounds "$rounds" --seed "${DEM_PROBE_SEED:-1}" "$@" \
  2>"$work/probe.err" | tee "$work/probe.out"
[ "${PIPESTATUS[0]}" -eq 0 ] || fail "the probe: $(tail -1 "$work/probe.out")"

if kill -0 "$server" 2>/dev/null; then
  ctl status >"$work/status.out" 2>&1 || fail "the server does not answer after the probe: $(cat "$work/status.out")"
  grep -q "state      running" "$work/status.out" || fail "the run was stopped: $(cat "$work/status.out")"
  ctl shutdown --force >/dev/null 2>&1 || fail "shutdown"
  wait "$server"
  code=$?
  server=""
  [ "$code" -eq 0 ] || fail "the server exited $code"
else
  wait "$server"
  fail "the server died (exit $?)"
  server=""
fi
if grep -q "Sanitizer" "$work/server.log"; then
  fail "a sanitizer reported:"
  grep -A30 "Sanitizer" "$work/server.log" | head -60
fi
[ "$failures" -eq 0 ] && echo "discovery probe: the server survived $rounds rounds" || tail -20 "$work/server.log"
exit $((failures > 0))
