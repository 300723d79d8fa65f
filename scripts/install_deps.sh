#!/usr/bin/env bash
# Installs every Debian package the build, the tests and the demo need.
# Idempotent and quiet: when everything is present it prints nothing and
# touches no package list.
set -euo pipefail

packages=(
  # toolchain
  cmake g++ make ccache
  # engine and case layer
  libeigen3-dev libprotobuf-dev protobuf-compiler libspdlog-dev libfmt-dev libcli11-dev libssl-dev
  # tests and benchmarks; the fuzz targets (clang's libFuzzer, OpenMP for clang)
  libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev libomp-dev
  # service (DDS) and its IDL compiler
  cyclonedds-dev cyclonedds-tools
  # Python client
  pybind11-dev python3-dev python3-protobuf python3-numpy python3-matplotlib python3-pytest
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "install_deps: missing packages: ${missing[*]} (run this script as root)" >&2
  exit 1
fi
echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
