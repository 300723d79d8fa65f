#!/usr/bin/env bash
# Installs every Debian package the build, the tests and the demo need (and
# unpacks ParaView's pvpython, below). Idempotent and quiet: when
# everything is present it prints nothing and touches no package list.
#   install_deps.sh [--build-only]   --build-only: what compiling and packaging need,
#                                    none of the tests' and the demo's tools (the image build)
set -euo pipefail
build_only=0
[ "${1:-}" = --build-only ] && build_only=1

packages=(
  # toolchain
  cmake g++ make ccache
  # engine and case layer
  libeigen3-dev libprotobuf-dev protobuf-compiler libspdlog-dev libfmt-dev libcli11-dev libssl-dev
  # tests and benchmarks; the fuzz targets (clang's libFuzzer, OpenMP for clang)
  libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev libomp-dev
  # the house style (.clang-format; the test code_format)
  clang-format
  # service (DDS) and its IDL compiler
  cyclonedds-dev cyclonedds-tools
  # Python client
  pybind11-dev python3-dev python3-protobuf python3-numpy python3-matplotlib python3-pytest
  # the Debian package (cpack: dpkg-shlibdeps, file)
  dpkg-dev file
)
if [ $build_only = 0 ]; then
  packages+=(
    # ParaView output: VTK reads the files back in tests; ParaView's pvpython renders the demo's picture
    # (headless, in Xvfb; unpacked below, as python3-paraview conflicts with python3-vtk9)
    python3-vtk9 paraview xvfb xauth
    # the live dashboard (dem.bridge: websockets, Chart.js) and its page test (headless Chromium)
    python3-websockets libjs-chart.js chromium chromium-driver python3-selenium
    # sweeps (docs/SWEEPS.md): a one-machine Slurm cluster for the job array test, Dask's
    # distributed scheduler for the Dask backend, ip(8) for the network namespace test
    slurmctld slurmd slurm-client munge python3-distributed iproute2
  )
  # Node.js and npm for the tests' independent readers (tests/npm), unless a
  # Node.js is installed already (from another source, with its own npm).
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    packages+=(nodejs npm)
  fi
fi

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
[ $build_only = 1 ] && exit 0
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
