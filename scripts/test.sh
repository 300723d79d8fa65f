#!/usr/bin/env bash
# Builds and runs every test (unit, validation, and the later suites).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
# Every DDS process uses the loopback-only configuration.
export CYCLONEDDS_URI="file://$root/config/cyclonedds-loopback.xml"
# ctest runs tests side by side, one per core: each test runs its physics on
# one thread (the determinism tests ask for two themselves), and OpenMP
# threads never spin, so no test waits on a descheduled thread.
export OMP_NUM_THREADS=1
export OMP_WAIT_POLICY=passive
cd "$root/build"
ctest --output-on-failure -j"$(nproc)"
