#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-fuzz/ and runs each for SECONDS
# (default 60), as many at once as there are cores (DEM_FUZZ_JOBS),
# starting from the seed corpus and the regression inputs in tests/fuzz;
# prints each target's executions, rate
# and coverage. A crash, a sanitizer report, a leak or an input slower than
# 10 s (DEM_FUZZ_TIMEOUT) fails the run; the input is saved in
# build-fuzz/findings/ (copy it to tests/fuzz/regressions/<target>/ with the
# fix: docs/FUZZING.md).
#   scripts/fuzz.sh [SECONDS] [TARGET ...]     targets: case_text case_binary snapshot command
# Part of scripts/test.sh (60 s each). New inputs the fuzzer finds
# interesting stay in build-fuzz/corpus/<target>/ for the next run, and each
# run adds a line to build-fuzz/fuzz_history.tsv (date, commit, target,
# seconds, executions, exec/s, cov, ft, corpus, exit code): the "total"
# column is a target's executions over every run in it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(case_text case_binary snapshot command)
build="${DEM_FUZZ_BUILD:-$root/build-fuzz}"
bash "$root/scripts/install_deps.sh"
# -O1 with line tables: the usual libFuzzer compromise of speed and reports.
cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DDEM_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1" \
  -DDEM_BUILD_TOOLS=OFF -DDEM_BUILD_BENCH=OFF -DDEM_BUILD_PYTHON=OFF -DDEM_BUILD_CLIENTS=OFF \
  -DDEM_CONTAINER_TEST=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
mkdir -p "$build/findings"
history="$build/fuzz_history.tsv"
[ -f "$history" ] || printf 'date\tcommit\ttarget\tseconds\texecutions\texec/s\tcov\tft\tcorpus\texit\n' >"$history"
commit=$(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)
# fuzz_one TARGET: runs one target for SECONDS; its log in fuzz_TARGET.log,
# its exit code in fuzz_TARGET.exit.
fuzz_one() {
  local target="$1" code=0
  local corpus="$build/corpus/$target"
  mkdir -p "$corpus"
  # A target without regressions has no directory for them (git keeps no
  # empty directory), and libFuzzer exits at a directory that is missing.
  local inputs=("$corpus") dir
  for dir in "$root/tests/fuzz/corpus/$target" "$root/tests/fuzz/regressions/$target"; do
    [ ! -d "$dir" ] || inputs+=("$dir")
  done
  "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout="${DEM_FUZZ_TIMEOUT:-10}" -rss_limit_mb=2560 \
    -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$build/findings/$target-" \
    "${inputs[@]}" >"$build/fuzz_$target.log" 2>&1 || code=$?
  echo "$code" >"$build/fuzz_$target.exit"
}
# The targets run side by side, a core each (DEM_FUZZ_JOBS, default every
# core): each is one process on one core, so four minutes of fuzzing take
# two on two cores and each target still gets its SECONDS of a core.
at_once="${DEM_FUZZ_JOBS:-$(nproc)}"
running=0
for target in "${targets[@]}"; do
  rm -f "$build/fuzz_$target.exit"
  fuzz_one "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$at_once" ]; then
    wait -n
    running=$((running - 1))
  fi
done
wait
failed=0
printf '%-12s %12s %10s %8s %8s %8s %12s\n' target executions exec/s cov ft corpus total
for target in "${targets[@]}"; do
  log="$build/fuzz_$target.log"
  code=$(cat "$build/fuzz_$target.exit" 2>/dev/null || echo 1)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  # "|| true": a log without a status line (the fuzzer did not start) must
  # not end the script under pipefail before it reports the target.
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  units=$(sed -n 's/.* corp: \([0-9]*\).*/\1/p' <<<"$last")
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%Y-%m-%dT%H:%M:%SZ)" "$commit" "$target" \
    "$seconds" "${runs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${units:-?}" "$code" >>"$history"
  total=$(awk -F'\t' -v t="$target" '$3 == t && $5 ~ /^[0-9]+$/ { n += $5 } END { print n + 0 }' "$history")
  printf '%-12s %12s %10s %8s %8s %8s %12s\n' "$target" "${runs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${units:-?}" "$total"
  if [ "$code" -ne 0 ]; then
    failed=1
    echo "fuzz_$target found a problem (exit $code); its log is $log:" >&2
    # Protocol Buffers' complaints about invalid UTF-8 are no finding. "|| true": under pipefail a
    # reader that stops early fails the pipeline, and set -e would end the script before the next target.
    grep -v 'libprotobuf ERROR' "$log" |
      grep -m 20 -E 'ERROR|SUMMARY|unexpected exception|Test unit written|runtime error' >&2 || true
  fi
done
exit "$failed"
