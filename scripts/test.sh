#!/usr/bin/env bash
# Builds and runs every test (unit, validation, service), then the service
# tests again under ThreadSanitizer (scripts/tsan.sh, in build-tsan/), then
# each fuzz target for a minute under ASan and UBSan (scripts/fuzz.sh, in
# build-fuzz/).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
# Every DDS process uses the loopback-only configuration.
export CYCLONEDDS_URI="file://$root/config/cyclonedds-loopback.xml"
# OpenMP threads must not spin while ctest runs tests side by side.
export OMP_WAIT_POLICY=passive
(cd "$root/build" && ctest --output-on-failure -j"$(nproc)")
bash "$root/scripts/tsan.sh"
bash "$root/scripts/fuzz.sh" 60
