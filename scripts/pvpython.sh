#!/usr/bin/env bash
# ParaView's pvpython, headless: run in a virtual X server (xvfb-run), from
# Debian's python3-paraview as scripts/install_deps.sh unpacked it (that
# package conflicts with python3-vtk9, so it is not installed).
#   bash scripts/pvpython.sh SCRIPT.py [ARGUMENTS...]
set -euo pipefail
paraview_dir="${DEM_PARAVIEW_DIR:-/var/cache/dem/paraview}"
pvpython="$paraview_dir/usr/bin/pvpython"
if [ ! -x "$pvpython" ]; then
  echo "pvpython.sh: no $pvpython (scripts/install_deps.sh unpacks it)" >&2
  exit 1
fi
exec xvfb-run -a "$pvpython" "$@"
