#!/usr/bin/env bash
# The README's test command, in three parts that each run whatever the
# others did:
#   1. build every target and run every test (ctest in build/: unit,
#      validation, service, Python, the container test, ...);
#   2. the service tests again under ThreadSanitizer (scripts/tsan.sh,
#      build-tsan/);
#   3. each fuzz target for a minute under ASan and UBSan (scripts/fuzz.sh,
#      build-fuzz/).
# It installs the packages the tests need first (scripts/install_deps.sh).
# At the end it prints each part's result and time, and exits 0 only when
# all three passed (otherwise 1; 2 when the packages could not be installed,
# as nothing can run then). ctest's log is build/ctest.log; the ten slowest
# tests of the run are printed after it (docs/PERFORMANCE.md keeps a
# profile).
#   DEM_CTEST_ARGS   ctest's selection for part 1; unset: every test but the
#                    image compiled from source (-LE container_source, docs/CONTAINERS.md),
#                    "" every test, "-L container_source" that one alone
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/lib/timing.sh"
test_start=$(clock)

if ! bash "$root/scripts/install_deps.sh" --for test; then
  echo "test.sh: the packages the tests need could not be installed" >&2
  exit 2
fi

# Every DDS process uses the loopback-only configuration.
export CYCLONEDDS_URI="file://$root/config/cyclonedds-loopback.xml"
# OpenMP threads must not spin while ctest runs tests side by side.
export OMP_WAIT_POLICY=passive

results=()
failed=0
# part NAME COMMAND...: runs one part, keeps its result and time.
part() {
  local name=$1 start code
  shift
  printf '\n==== %s\n' "$name"
  start=$(clock)
  "$@"
  code=$?
  if [ $code -eq 0 ]; then
    results+=("$(printf '%-40s passed   %s' "$name" "$(since "$start")")")
  else
    failed=1
    results+=("$(printf '%-40s FAILED   %s (exit %d)' "$name" "$(since "$start")" "$code")")
  fi
}

ctest_part() {
  bash "$root/scripts/build.sh" || return
  local log="$root/build/ctest.log" code
  # shellcheck disable=SC2086  # DEM_CTEST_ARGS is a list of arguments
  (cd "$root/build" && ctest --output-on-failure -j"$(nproc)" ${DEM_CTEST_ARGS--LE container_source}) 2>&1 | tee "$log"
  code=${PIPESTATUS[0]}
  echo
  echo "the ten slowest tests of this run:"
  # "  3/345 Test #117: name .......   Passed    0.05 sec" (or ***Failed, ***Timeout).
  awk '/ Test +#[0-9]+: / && $NF == "sec" { for (i = 1; i < NF; ++i) if ($i ~ /^#[0-9]+:$/) name = $(i + 1);
       status = $(NF - 2); gsub(/^[.*]+/, "", status); printf "%10.1f s  %s  %s\n", $(NF - 1), name, status }' "$log" | sort -rn | head -10
  return "$code"
}

part "1. build and ctest (build/)" ctest_part
part "2. ThreadSanitizer (build-tsan/)" bash "$root/scripts/tsan.sh"
part "3. fuzz, 60 s a target (build-fuzz/)" bash "$root/scripts/fuzz.sh" 60

printf '\n==== test.sh: each part\n'
printf '  %s\n' "${results[@]}"
printf '  %-40s %s   %s\n' "all" "$([ $failed = 0 ] && echo passed || echo FAILED)" "$(since "$test_start")"
exit $failed
