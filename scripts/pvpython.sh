#!/usr/bin/env bash
# ParaView's pvpython, headless: in a virtual X server of its own (Xvfb),
# from Debian's python3-paraview as scripts/install_deps.sh unpacked it
# (that package conflicts with python3-vtk9, so it is not installed).
#   bash scripts/pvpython.sh SCRIPT.py [ARGUMENTS...]
# Xvfb picks a free display and says which once it accepts connections
# (-displayfd), and never resets (-noreset): an X server resets when its
# last client leaves, and pvpython, which connects more than once, then
# failed about one run in five under xvfb-run ("bad X server connection").
set -euo pipefail
paraview_dir="${DEM_PARAVIEW_DIR:-/var/cache/dem/paraview}"
pvpython="$paraview_dir/usr/bin/pvpython"
if [ ! -x "$pvpython" ]; then
  echo "pvpython.sh: no $pvpython (scripts/install_deps.sh unpacks it)" >&2
  exit 1
fi
work=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1920x1200x24 -nolisten tcp -noreset 3>"$work/display" 2>"$work/xvfb.log" &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null || true; wait "$xvfb" 2>/dev/null || true; rm -rf "$work"' EXIT
for _ in $(seq 100); do
  [ -s "$work/display" ] && break
  kill -0 "$xvfb" 2>/dev/null || { echo "pvpython.sh: Xvfb did not start:" >&2; cat "$work/xvfb.log" >&2; exit 1; }
  sleep 0.1
done
[ -s "$work/display" ] || { echo "pvpython.sh: Xvfb named no display in 10 s" >&2; exit 1; }
DISPLAY=":$(head -1 "$work/display")" "$pvpython" "$@"
