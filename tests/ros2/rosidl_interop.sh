#!/usr/bin/env bash
# Starts a dem_server with a case loaded and telemetry every 10 cycles, runs
# rosidl_interop against it (which shuts it down at the end), and passes when
# both end with 0.
#   rosidl_interop.sh DEM_SERVER ROSIDL_INTEROP CASE OUT DOMAIN
set -euo pipefail
dem_server="$1" interop="$2" case_file="$3" out="$4" domain="$5"
rm -rf "$out" && mkdir -p "$out"
"$dem_server" --name interop --domain "$domain" --case "$case_file" --telemetry-cycles 10 --threads 1 \
  --out "$out" --log-level warn >"$out/dem_server.log" 2>&1 &
server=$!
trap 'kill -9 $server 2>/dev/null || true' EXIT
status=0
"$interop" "$domain" interop 10 || status=$?
if ! wait "$server"; then
  echo "dem_server failed; its log:" >&2
  cat "$out/dem_server.log" >&2
  status=1
fi
trap - EXIT
exit $status
