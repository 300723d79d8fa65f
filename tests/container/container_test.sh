#!/usr/bin/env bash
# The container test (ctest label container), on podman as
# ../shared/CONTAINERS.md describes it:
#   1. sets podman up (scripts/container_setup.sh) and builds the image
#      (docker/build.sh) - from the Debian package of the host's build
#      (cpack in BUILD_DIR, then docker/build.sh --deb), as a user's CI does
#      with the package its build job made; with --from-source (label
#      container_source) compiling the project in the image's build stage,
#      as the README's image build does: labels, user, stop signal and
#      HEALTHCHECK as built;
#   2. starts dem_server in a container (host network, the repository's
#      loopback configuration mounted and passed in, a host directory as
#      /data) and drives it from demctl on the host: load, a loading stage
#      with cycle, contact query, monitor to CSV, snapshots
#      (docker/experiment.sh); checks the HEALTHCHECK reports it healthy, and
#      unhealthy for a container without a server;
#   3. stops it with SIGTERM (podman stop): a clean exit 0, in time, and its
#      tables and snapshot on the volume;
#   4. the one-shot mode in a container: exit 0 with the tables, stages.csv
#      and final.snapshot; an unstable case: exit 1, the error in the log and
#      last_good.snapshot;
#   5. docker/compose.yaml's services, run one by one with podman
#      (compose_run.py): the server with the experiment client, and the pair
#      profile's two servers addressed by name.
# Prints how long each step took. Skips (exit 77) only where podman cannot
# run: not root, podman not installable, or no container can start.
#   container_test.sh SOURCE_DIR BUILD_DIR DEMCTL WORK_DIR DOMAIN [--from-source]   (uses DOMAIN to DOMAIN + 3)
set -euo pipefail
root="$1"
build_dir="$2"
demctl="$3"
work="$4"
domain="$5"
from_source=0
[ "${6:-}" = --from-source ] && from_source=1

start=$(date +%s)
step() { printf '\n== [%4ss] %s\n' "$(($(date +%s) - start))" "$*"; }
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
# At least `count` data rows (beyond the header) in a CSV file.
rows_at_least() {
  local file="$1" count="$2" rows
  [ -f "$file" ] || fail "missing $file"
  rows=$(($(wc -l <"$file") - 1))
  [ "$rows" -ge "$count" ] || fail "$file has $rows rows, expected at least $count"
}
# A CSV column's value in the last row, by the column's name.
last_value() {
  awk -F, -v column="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == column) c = i } END { print $c }' "$1"
}

# The host's DDS processes (demctl) on loopback, like the containers'.
export CYCLONEDDS_URI="file://$root/config/cyclonedds-loopback.xml"
unset DEM_SERVER DEM_DOMAIN

# ctest reports this code as a skip (SKIP_RETURN_CODE in CMakeLists.txt):
# only where podman cannot run at all, never for a failure of the image or
# of what runs in it.
skip() {
  echo "SKIP: $*" >&2
  exit 77
}

rm -rf "$work"
mkdir -p "$work"

step "setting podman up (scripts/container_setup.sh)"
# podman on these machines needs root: the setup installs packages and
# builds the base image, and rootless podman has no user namespace here.
[ "$(id -u)" = 0 ] || skip "the container test runs podman as root, and this is uid $(id -u)"
if ! CONTAINERS_CONF="$(bash "$root/scripts/container_setup.sh" 2>"$work/setup.log")"; then
  cat "$work/setup.log" >&2
  command -v podman >/dev/null || skip "podman is not installed and could not be installed (log above)"
  fail "scripts/container_setup.sh failed (log above)"
fi
cat "$work/setup.log" >&2
export CONTAINERS_CONF
# A container of the base image that does nothing: if that cannot run (no
# namespaces or cgroups for runc, as in some sandboxes), nothing can.
if ! podman run --rm --network host --pull=never docker.io/library/debian:bookworm true 2>"$work/probe.log"; then
  skip "podman cannot run a container here: $(tail -n 3 "$work/probe.log" | tr '\n' ' ')"
fi

# Names of this run's image, containers and volumes: one source tree keeps
# one image tag (its layers stay cached for the next run); containers and
# volumes are this run's own, removed at the end.
tree_id=$(printf '%s' "$root" | md5sum | cut -c1-8)
image="localhost/dem:ctest-$tree_id"
[ $from_source = 0 ] || image+="-source"
project="demctest_${tree_id}_$$"
# shellcheck disable=SC2086  # $names: one container or volume per word
cleanup() {
  local names
  names=$(podman ps -a --format '{{.Names}}' | grep "^${project}_" || true)
  [ -z "$names" ] || podman rm -f -v -t 0 $names >/dev/null 2>&1 || true
  names=$(podman volume ls --format '{{.Name}}' | grep "^${project}_" || true)
  [ -z "$names" ] || podman volume rm -f $names >/dev/null 2>&1 || true
}
trap cleanup EXIT
# Inside the containers: the repository's loopback configuration, mounted.
config=(--volume "$root/config/cyclonedds-loopback.xml:/etc/dem/cyclonedds.xml:ro"
  --env CYCLONEDDS_URI=file:///etc/dem/cyclonedds.xml)
# A host directory the image's user (uid 10001) may write, as /data.
data_dir() {
  mkdir -p "$1"
  chown 10001:10001 "$1"
}

build_start=$(date +%s)
# Each line of the build's log with the time it came, to see where the time goes.
stamped() { while IFS= read -r line; do printf '%(%T)T %s\n' -1 "$line"; done; }
image_id() { podman image inspect --format '{{.Id}}' "$1" 2>/dev/null || true; }
if [ $from_source = 0 ]; then
  step "packing the host's build (cpack in $build_dir; log in $work/cpack.log)"
  (cd "$work" && cpack --config "$build_dir/CPackConfig.cmake" -B "$work/deb" >"$work/cpack.log" 2>&1) ||
    { tail -n 30 "$work/cpack.log"; fail "cpack"; }
  deb=$(ls "$work"/deb/dem_*_amd64.deb)
  step "building $image from $(basename "$deb") (docker/build.sh --deb; log in $work/build.log)"
  previous=("$(image_id "$image")")
  # shellcheck disable=SC2086  # DEM_IMAGE_BUILD_OPTIONS: extra options, e.g. --no-cache
  if ! DEM_IMAGE="$image" bash "$root/docker/build.sh" --deb "$deb" --pull=never --network host \
    ${DEM_IMAGE_BUILD_OPTIONS:-} 2>&1 | stamped >"$work/build.log"; then  # pipefail: the build's own status
    tail -n 60 "$work/build.log"
    fail "the image did not build"
  fi
else
  step "building $image from source (docker/build.sh; log in $work/build.log)"
  # The images this tag and its build stage's tag name now: replaced by the
  # build, they are removed after it, so repeated runs do not pile up stale
  # layers (the build stage's are 1.6 GB). Tagging the build stage keeps its
  # layers, the packages and the compile, as the cache of the next run.
  stage_image="$image-build"
  previous=("$(image_id "$image")" "$(image_id "$stage_image")")
  # shellcheck disable=SC2086  # DEM_IMAGE_BUILD_OPTIONS: extra options, e.g. --no-cache
  if ! DEM_IMAGE="$image" bash "$root/docker/build.sh" --pull=never --network host ${DEM_IMAGE_BUILD_OPTIONS:-} 2>&1 |
    stamped >"$work/build.log"; then  # pipefail: the build's own status
    tail -n 60 "$work/build.log"
    fail "the image did not build"
  fi
  # The build stage's image: the last layer the log names ("--> ID" or
  # "--> Using cache ID") before the stage that takes its package starts.
  stage_id=$(awk '/ STEP 1\/[0-9]+: FROM .* AS package/{ print id; exit } / --> /{ id = $NF }' "$work/build.log")
  [ -n "$stage_id" ] && podman tag "$stage_id" "$stage_image" 2>>"$work/podman.log" ||
    fail "the build stage's image is not in $work/build.log"
fi
for id in "${previous[@]}"; do
  [ -n "$id" ] && [ "$id" != "$(image_id "$image")" ] || continue
  [ -z "${stage_image:-}" ] || [ "$id" != "$(image_id "$stage_image")" ] || continue
  podman rmi "$id" >/dev/null 2>>"$work/podman.log" || true
done
grep -E '^[0-9:]+ +(Hits|Misses):' "$work/build.log" | sed -E 's/^[0-9:]+ +/ccache /' || true
size=$(podman image inspect --format '{{.Size}}' "$image")
build_seconds=$(($(date +%s) - build_start))
echo "built in $build_seconds s; image size $((size / 1000000)) MB"

version=$(sed -n 's/^project(dem VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
label() { podman image inspect --format "{{index .Labels \"org.opencontainers.image.$1\"}}" "$image"; }
[ "$(label version)" = "$version" ] || fail "version label '$(label version)', expected $version"
[ -n "$(label source)" ] && [ "$(label source)" != unknown ] || fail "no source label"
[ "$(podman image inspect --format '{{.User}}' "$image")" = dem ] || fail "the image does not run as user dem"
[ "$(podman image inspect --format '{{.Config.StopSignal}}' "$image")" = SIGTERM ] || fail "stop signal is not SIGTERM"
podman image inspect --format '{{.HealthCheck.Test}}' "$image" | grep -q 'demctl' || fail "no HEALTHCHECK with demctl"
# (podman's stderr goes to podman.log: on machines without systemd it
# reports, harmlessly, that it cannot schedule the HEALTHCHECK.)
podman run --rm --network host "$image" --help >/dev/null 2>>"$work/podman.log" ||
  fail "dem_server --help fails in the image"
podman run --rm --network host --entrypoint dem_run "$image" --help >/dev/null 2>>"$work/podman.log" ||
  fail "dem_run --help fails in the image"
[ "$(podman run --rm --network host --entrypoint id "$image" -u 2>>"$work/podman.log")" = 10001 ] ||
  fail "the container's uid is not 10001"
# The image holds the project as the Debian package CPack built, installed by apt.
[ "$(podman run --rm --network host --entrypoint dpkg-query "$image" -W -f '${Version}' dem 2>>"$work/podman.log")" = \
  "$version" ] || fail "the image's package dem is not version $version"
podman run --rm --network host --entrypoint python3 "$image" -c \
  "import dem, dem._client; assert dem.__version__ == '$version'; print(dem.paths.server_program())" \
  >"$work/python.out" 2>>"$work/podman.log" || fail "the Python package does not import in the image"
[ "$(cat "$work/python.out")" = /usr/bin/dem_server ] || fail "the Python package finds $(cat "$work/python.out"), not /usr/bin/dem_server"

step "server container: dem_server \"ctest\" on domain $domain, /data = $work/server"
data_dir "$work/server"
server="${project}_host_driven"
podman run --detach --name "$server" --network host "${config[@]}" \
  --env DEM_SERVER=ctest --env DEM_DOMAIN="$domain" --env DEM_TELEMETRY_CYCLES=10 \
  --volume "$work/server:/data" "$image" >/dev/null 2>>"$work/podman.log" || fail "$(cat "$work/podman.log")"
# The same HEALTHCHECK on a container whose server never starts must fail.
podman run --detach --name "${project}_idle" --network host "${config[@]}" \
  --env DEM_SERVER=ctest_idle --env DEM_DOMAIN="$domain" --entrypoint sleep "$image" 300 \
  >/dev/null 2>>"$work/podman.log" || fail "$(cat "$work/podman.log")"
podman healthcheck run "${project}_idle" >"$work/idle_health.txt" 2>&1 &
idle_check=$!

step "driving it from demctl on the host (docker/experiment.sh)"
DEMCTL="$demctl" DEM_SERVER=ctest DEM_DOMAIN="$domain" EXPERIMENT_SHUTDOWN=0 \
  EXPERIMENT_CASE="$root/cases/ball/nine_disc_damped.case.txtpb" EXPERIMENT_OUT="$work/host" \
  bash "$root/docker/experiment.sh" >"$work/experiment.log" 2>&1 || {
  cat "$work/experiment.log"
  podman logs "$server" | tail -n 30
  fail "the experiment failed"
}
grep -q "loaded case nine_disc_damped" "$work/experiment.log" || fail "the case was not loaded"
grep -q "ran 40 cycles" "$work/experiment.log" || fail "the loading stage did not run its 40 cycles"
rows_at_least "$work/host/monitor.csv" 45
head -n 1 "$work/host/monitor.csv" | grep -q '^cycle,time,top_stress,top_settlement,' || fail "monitor.csv header"
settlement=$(last_value "$work/host/monitor.csv" top_settlement)
awk -v s="$settlement" 'BEGIN { exit !(s > 4.79 && s < 4.81) }' || fail "top settlement $settlement, expected 4.8"
rows_at_least "$work/host/contacts.csv" 1
[ -s "$work/host/final.snapshot" ] || fail "no snapshot transferred to the host"
echo "monitor.csv: $(($(wc -l <"$work/host/monitor.csv") - 1)) rows, top settlement $settlement m"

step "HEALTHCHECK"
podman healthcheck run "$server" >"$work/health.txt" 2>&1 || {
  cat "$work/health.txt"
  fail "the server container is not healthy"
}
health=$(podman inspect --format '{{.State.Health.Status}}' "$server" 2>/dev/null ||
  podman inspect --format '{{.State.Healthcheck.Status}}' "$server")
[ "$health" = healthy ] || fail "health status '$health'"
if wait "$idle_check"; then fail "the HEALTHCHECK passed without a server: $(cat "$work/idle_health.txt")"; fi
grep -q unhealthy "$work/idle_health.txt" || fail "no unhealthy report: $(cat "$work/idle_health.txt")"
echo "server: $health; a container without a server: unhealthy"

step "stopping it with SIGTERM (podman stop)"
stop_start=$(date +%s)
podman stop --time 30 "$server" >/dev/null 2>>"$work/podman.log"
stop_seconds=$(($(date +%s) - stop_start))
podman logs "$server" >"$work/server.log" 2>&1
code=$(podman inspect --format '{{.State.ExitCode}}' "$server")
[ "$code" = 0 ] || fail "the server exited with $code: $(tail -n 20 "$work/server.log")"
[ "$stop_seconds" -lt 10 ] || fail "the server took $stop_seconds s to stop (killed at the timeout?)"
grep -q "received SIGTERM: shutting down" "$work/server.log" || fail "no SIGTERM in the server's log"
grep -q "shut down at cycle 500" "$work/server.log" || fail "no clean shutdown at cycle 500 in the log"
for file in walls.csv assembly.csv contacts.csv particles.csv; do
  rows_at_least "$work/server/nine_disc_damped/$file" 1
done
rows_at_least "$work/server/nine_disc_damped/walls.csv" $((51 * 4))
[ -s "$work/server/experiment.snapshot" ] || fail "no snapshot saved on the server's volume"
[ "$(stat -c %u "$work/server/nine_disc_damped/walls.csv")" = 10001 ] || fail "the files are not the container user's"
echo "exit 0 after ${stop_seconds} s; on the volume: nine_disc_damped/{walls,assembly,contacts,particles}.csv, experiment.snapshot"

step "one-shot mode in a container: --case ... --run-and-exit"
data_dir "$work/batch"
podman run --rm --name "${project}_batch" --network host "${config[@]}" \
  --env DEM_SERVER=batch --env DEM_DOMAIN=$((domain + 1)) --volume "$work/batch:/data" \
  "$image" --case /opt/dem/cases/ball/nine_disc_damped.case.txtpb --run-and-exit >"$work/batch.log" 2>&1 ||
  fail "the one-shot run exited with $?: $(tail -n 20 "$work/batch.log")"
results="$work/batch/nine_disc_damped"
for file in walls.csv assembly.csv contacts.csv particles.csv; do rows_at_least "$results/$file" 1; done
rows_at_least "$results/walls.csv" $((301 * 4))  # the case's output interval, 10 cycles
[ "$(cut -d, -f2,5 "$results/stages.csv" | tr '\n' ' ')" = "name,cycle compress,40 hold,3000 " ] ||
  fail "stages.csv: $(cat "$results/stages.csv")"
[ -s "$results/final.snapshot" ] || fail "no final.snapshot"
grep -q "programme complete at cycle 3000" "$work/batch.log" || fail "no completion in the log"

step "one-shot mode, a run that fails: exit 1, the error logged, the last good state"
data_dir "$work/failed"
set +e
podman run --rm --name "${project}_failed" --network host "${config[@]}" \
  --env DEM_SERVER=failing --env DEM_DOMAIN=$((domain + 1)) --volume "$work/failed:/data" \
  --volume "$root/tests/service/data:/cases:ro" "$image" --case /cases/blows_up.case.txtpb --run-and-exit \
  >"$work/failed.log" 2>&1
code=$?
set -e
[ "$code" = 1 ] || fail "the failed run exited with $code: $(tail -n 20 "$work/failed.log")"
grep -q "programme failed: the run is unhealthy" "$work/failed.log" || fail "no error in the log"
[ -s "$work/failed/blows_up/last_good.snapshot" ] || fail "no last_good.snapshot"
[ ! -e "$work/failed/blows_up/final.snapshot" ] || fail "a final.snapshot of a failed run"
grep "programme failed" "$work/failed.log" | tail -n 1

compose="$root/docker/compose.yaml"
run_service() { DEM_IMAGE="$image" /usr/bin/python3 "$root/tests/container/compose_run.py" "$compose" "$@" --project "$project"; }
volume_dir() { podman volume inspect --format '{{.Mountpoint}}' "${project}_dem-data"; }

step "compose.yaml: server + experiment (domain $((domain + 2)))"
export DEM_DOMAIN=$((domain + 2)) DEM_PAIR_DOMAIN=$((domain + 3))
run_service server --detach >/dev/null 2>>"$work/podman.log" || fail "$(tail -n 5 "$work/podman.log")"
run_service experiment >"$work/compose_experiment.log" 2>&1 || {
  cat "$work/compose_experiment.log"
  fail "the compose experiment failed"
}
[ "$(podman wait "${project}_server")" = 0 ] || fail "the compose server did not exit 0 after the experiment"
rows_at_least "$(volume_dir)/experiment/monitor.csv" 45
rows_at_least "$(volume_dir)/experiment/contacts.csv" 1
rows_at_least "$(volume_dir)/nine_disc_damped/walls.csv" 1
[ -s "$(volume_dir)/experiment/final.snapshot" ] || fail "no snapshot from the compose experiment"

step "compose.yaml, profile pair: two servers addressed by name (domain $((domain + 3)))"
run_service press_a --detach >/dev/null 2>>"$work/podman.log" || fail "$(tail -n 5 "$work/podman.log")"
run_service press_b --detach >/dev/null 2>>"$work/podman.log" || fail "$(tail -n 5 "$work/podman.log")"
run_service pair >"$work/compose_pair.log" 2>&1 || {
  cat "$work/compose_pair.log"
  fail "the pair client failed"
}
grep -q "^press_a " "$work/compose_pair.log" && grep -q "^press_b " "$work/compose_pair.log" ||
  fail "demctl servers did not list both: $(cat "$work/compose_pair.log")"
[ "$(podman wait "${project}_press_a")" = 0 ] && [ "$(podman wait "${project}_press_b")" = 0 ] ||
  fail "the pair's servers did not exit 0"
# Each server ran its own loading: press_b's plate moved at half the speed.
a=$(last_value "$(volume_dir)/pair/press_a/monitor.csv" top_settlement)
b=$(last_value "$(volume_dir)/pair/press_b/monitor.csv" top_settlement)
awk -v a="$a" -v b="$b" 'BEGIN { exit !(a > 4.79 && a < 4.81 && b > 2.39 && b < 2.41) }' ||
  fail "settlements $a (press_a) and $b (press_b), expected 4.8 and 2.4"
echo "press_a settled $a m, press_b $b m"

step "done: the container test passed in $(($(date +%s) - start)) s, $build_seconds s of it building the image ($((size / 1000000)) MB)"
