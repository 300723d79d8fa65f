#!/usr/bin/env bash
# The main job: builds the project and runs BALL's verification assembly
# (Cundall & Strack 1979) headless, then the nine-disc validation, and shows
# the results. Outputs go to out/ (or the directory given as $1).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/out}"
bash "$root/scripts/build.sh"
echo
"$root/build/tools/dem_run/dem_run" "$root/cases/ball/verification_assembly.case.txtpb" --out "$out/verification"
echo
"$root/build/tools/dem_validate/dem_validate" nine-disc --out "$out/validation"
echo
echo "Results: $out/verification/{walls,assembly,contacts,particles}.csv and $out/validation/nine_disc*.csv"
