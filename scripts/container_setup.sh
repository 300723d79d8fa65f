#!/usr/bin/env bash
# Makes podman able to build and run docker/Dockerfile on these machines
# (../shared/CONTAINERS.md explains why each step is needed):
#   1. the Debian packages podman needs here (runc, not crun), and PyYAML
#      for tests/container/compose_run.py;
#   2. a containers.conf that picks runc and caps the containers' rlimits at
#      this machine's hard limits (podman's default nofile of 1048576 fails);
#   3. the base image docker.io/library/debian:bookworm, built with
#      debootstrap from the configured Debian archive (no registry is
#      reachable), with that archive's apt settings inside.
# Idempotent: what is there already is left alone, and then it prints only
# the path of the containers.conf on stdout, so callers do
#   export CONTAINERS_CONF="$(bash scripts/container_setup.sh)"
# Progress goes to stderr. Runs as root. DEM_PODMAN_DIR (default
# /var/tmp/dem-podman) holds the configuration and the lock that keeps two
# setups from building the base image at once.
set -euo pipefail

dir="${DEM_PODMAN_DIR:-/var/tmp/dem-podman}"
base_image=docker.io/library/debian:bookworm
packages=(podman runc debootstrap containernetworking-plugins iptables python3-yaml)

say() { echo "container_setup: $*" >&2; }

if [ "$(id -u)" -ne 0 ]; then
  say "run this script as root (it installs packages and builds the base image)"
  exit 1
fi

# 1. packages, installed only when missing (as scripts/install_deps.sh does)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# 2. containers.conf, rewritten only when its content would change
mkdir -p "$dir"
nofile=$(ulimit -Hn)
nproc=$(ulimit -Hu)
[ "$nproc" = unlimited ] || [ "$nproc" -gt 32768 ] && nproc=32768
conf="$dir/containers.conf"
wanted=$(cat <<EOF
# Written by scripts/container_setup.sh: podman on these machines.
[containers]
default_ulimits = ["nofile=${nofile}:${nofile}", "nproc=${nproc}:${nproc}"]
[engine]
runtime = "runc"
cgroup_manager = "cgroupfs"
events_logger = "file"
EOF
)
if [ ! -f "$conf" ] || [ "$(cat "$conf")" != "$wanted" ]; then
  printf '%s\n' "$wanted" >"$conf.tmp"
  mv "$conf.tmp" "$conf"
fi
export CONTAINERS_CONF="$conf"

# 3. the base image, once; the lock makes a second setup wait for the first
exec 9>"$dir/setup.lock"
flock 9
if ! podman image exists "$base_image"; then
  say "building $base_image with debootstrap (about a minute)"
  mirror=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources)
  rootfs="$dir/rootfs"
  rm -rf "$rootfs"
  debootstrap --variant=minbase bookworm "$rootfs" "$mirror" >"$dir/debootstrap.log" 2>&1 ||
    { say "debootstrap failed; see $dir/debootstrap.log"; exit 1; }
  # The archive's sources and its apt settings (Check-Valid-Until false for
  # a snapshot archive), so apt-get inside image builds reaches the same archive.
  rm -f "$rootfs/etc/apt/sources.list"
  cp /etc/apt/sources.list.d/debian.sources "$rootfs/etc/apt/sources.list.d/"
  for f in $(grep -l '^Acquire::Check' /etc/apt/apt.conf.d/* || true); do cp "$f" "$rootfs/etc/apt/apt.conf.d/"; done
  rm -rf "$rootfs"/var/cache/apt/archives/*.deb "$rootfs"/var/lib/apt/lists/*
  tar -C "$rootfs" -c . | podman import --quiet --change 'CMD ["/bin/bash"]' - localhost/debian:bookworm >/dev/null
  rm -rf "$rootfs"
  podman tag localhost/debian:bookworm "$base_image" docker.io/library/debian:12
fi
flock -u 9

echo "$conf"
