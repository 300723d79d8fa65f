#!/usr/bin/env bash
# Installs the Debian packages (if missing) and builds in build/ (Release,
# the default), printing how long each part took.
#   build.sh [--for demo] [CMAKE CONFIGURE ARGUMENTS...]
#     (default)   every target: programs, libraries, tests, benchmarks
#     --for demo  only what scripts/demo.sh runs: dem_server, demctl and the
#                 Python client (tests and benchmarks are not configured, so
#                 their packages are not needed)
# At a terminal the compile's progress is one line (the share done and the
# file at hand); elsewhere (a CI log) a line every tenth. The compiler's
# whole output is in build/build.log, and its end is printed on a failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/lib/timing.sh"
job=build
if [ "${1:-}" = --for ]; then
  job="$2"
  shift 2
fi
case "$job" in
  build) options=(-DDEM_BUILD_TESTS=ON -DDEM_BUILD_BENCH=ON) targets=(all) ;;
  demo) options=(-DDEM_BUILD_TESTS=OFF -DDEM_BUILD_BENCH=OFF) targets=(dem_server demctl dem_python) ;;
  *) echo "build.sh: unknown --for $job (demo, or nothing for every target)" >&2; exit 2 ;;
esac

start=$(clock)
bash "$root/scripts/install_deps.sh" --for "$job"
echo "build: packages checked in $(since "$start")"

start=$(clock)
mkdir -p "$root/build"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "${options[@]}" "$@" >"$root/build/configure.log" 2>&1 ||
  { cat "$root/build/configure.log" >&2; exit 1; }
echo "build: configured in $(since "$start")"

start=$(clock)
log="$root/build/build.log"
tty=0
[ -t 1 ] && tty=1
shown=-10
set +e
cmake --build "$root/build" -j"$(nproc)" --target "${targets[@]}" 2>&1 | tee "$log" | while IFS= read -r line; do
  # Make's "[ 45%] Building CXX object engine/CMakeFiles/dem_engine.dir/src/world.cpp.o".
  [[ $line =~ ^\[\ *([0-9]+)%\]\ (.*)$ ]] || continue
  percent=${BASH_REMATCH[1]}
  what=${BASH_REMATCH[2]}
  what=${what/CMakeFiles\/*.dir\//}
  if [ $tty = 1 ]; then
    printf '\r\033[Kbuild: [%3d%%] %.100s' "$percent" "$what"
  elif [ "$percent" -ge $((shown + 10)) ]; then
    shown=$percent
    printf 'build: [%3d%%] %s\n' "$percent" "$what"
  fi
done
status=${PIPESTATUS[0]}
set -e
[ $tty = 1 ] && printf '\r\033[K'
if [ "$status" -ne 0 ]; then
  echo "build: the compile failed after $(since "$start"); the end of $log:" >&2
  grep -v '^\[ *[0-9]*%\]' "$log" | tail -40 >&2
  exit "$status"
fi
echo "build: ${targets[*]} compiled in $(since "$start") ($(grep -c 'Building C' "$log" || true) files compiled; log $log)"
