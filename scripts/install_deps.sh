#!/usr/bin/env bash
# Installs the Debian packages one job needs (and unpacks ParaView's
# pvpython for the jobs that draw with it, below). Idempotent and quiet:
# when everything is present it prints nothing and touches no package list.
#   install_deps.sh [--for JOB]
#     test     (the default) everything: the build of every target, the
#              tests' tools (ParaView, VTK, headless Chromium, a Slurm
#              cluster, Dask, Node.js), the fuzz targets' clang, the demo's
#     build    compiling every target of build/ (tests and benchmarks
#              included) and packing the Debian package (scripts/build.sh)
#     demo     what scripts/demo.sh builds and runs: dem_server, demctl and
#              the Python client, the dashboard, the plots and pvpython
#     package  compiling the package's targets (tests and benchmarks off) and
#              packing it: the image's build stage (docker/Dockerfile)
#   --build-only is the old name of --for package.
set -euo pipefail
job=test
case "${1:-}" in
  "") ;;
  --build-only) job=package ;;
  --for) job="${2:-}" ;;
  *) echo "install_deps: unknown argument $1 (--for test|build|demo|package)" >&2; exit 2 ;;
esac

# What compiles dem_server, demctl and the Python client, and every library under them.
compile=(
  cmake g++ make ccache
  # engine and case layer
  libeigen3-dev libprotobuf-dev protobuf-compiler libspdlog-dev libfmt-dev libcli11-dev libssl-dev
  # service (DDS) and its IDL compiler
  cyclonedds-dev cyclonedds-tools
  # Python client
  pybind11-dev python3-dev python3-protobuf python3-numpy
)
# The Debian package (cpack: dpkg-shlibdeps, file).
packaging=(dpkg-dev file)
# The tests and benchmarks of build/, and the house style (.clang-format; the test code_format).
test_compile=(libgtest-dev libgmock-dev libbenchmark-dev clang-format)
# The demo's run: the plots, the live dashboard (dem.bridge: websockets, Chart.js), and
# ParaView's pvpython for the force-chain picture (headless, in Xvfb; unpacked below,
# as python3-paraview conflicts with python3-vtk9).
demo_run=(python3-matplotlib python3-websockets libjs-chart.js paraview xvfb xauth)
test_run=(
  python3-pytest
  # the fuzz targets (clang's libFuzzer; OpenMP for clang)
  clang libclang-rt-14-dev libomp-dev
  # VTK reads the ParaView files back in tests
  python3-vtk9
  # the dashboard's page test (headless Chromium)
  chromium chromium-driver python3-selenium
  # sweeps (docs/SWEEPS.md): a one-machine Slurm cluster for the job array test, Dask's
  # distributed scheduler for the Dask backend, ip(8) for the network namespace test
  slurmctld slurmd slurm-client munge python3-distributed iproute2
)

case "$job" in
  package) packages=("${compile[@]}" "${packaging[@]}") ;;
  demo) packages=("${compile[@]}" "${demo_run[@]}") ;;
  build) packages=("${compile[@]}" "${packaging[@]}" "${test_compile[@]}") ;;
  test)
    packages=("${compile[@]}" "${packaging[@]}" "${test_compile[@]}" "${demo_run[@]}" "${test_run[@]}")
    # Node.js and npm for the tests' independent readers (tests/npm), unless a
    # Node.js is installed already (from another source, with its own npm).
    if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
      packages+=(nodejs npm)
    fi
    ;;
  *) echo "install_deps: unknown job \"$job\" (test, build, demo or package)" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "install_deps: missing packages: ${missing[*]} (run this script as root)" >&2
    exit 1
  fi
  echo "install_deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# pvpython: Debian puts it in python3-paraview, which conflicts with
# python3-vtk9 (both ship the Python module vtkmodules). It runs as well
# unpacked from the package beside the installed paraview of the same
# version, with its own modules first: scripts/pvpython.sh runs it from
# $DEM_PARAVIEW_DIR (default /var/cache/dem/paraview).
[ "$job" = demo ] || [ "$job" = test ] || exit 0
paraview_dir="${DEM_PARAVIEW_DIR:-/var/cache/dem/paraview}"
paraview_version=$(dpkg-query -W -f='${Version}' paraview)
if [ "$(cat "$paraview_dir/version" 2>/dev/null)" != "$paraview_version" ]; then
  if [ "$(id -u)" -ne 0 ] && [ ! -w "$(dirname "$paraview_dir")" ]; then
    echo "install_deps: $paraview_dir needs python3-paraview $paraview_version unpacked (run this script as root)" >&2
    exit 1
  fi
  echo "install_deps: unpacking python3-paraview $paraview_version into $paraview_dir"
  download=$(mktemp -d)
  chmod 755 "$download"  # apt's download user must write here
  (cd "$download" && { apt-get download -qq "python3-paraview=$paraview_version" 2>/dev/null ||
    { apt-get update -qq && apt-get download -qq "python3-paraview=$paraview_version" 2>/dev/null; }; })
  rm -rf "$paraview_dir" && mkdir -p "$paraview_dir"
  dpkg-deb -x "$download"/python3-paraview_*.deb "$paraview_dir"
  rm -rf "$download"
  echo "$paraview_version" >"$paraview_dir/version"
fi
