#!/usr/bin/env bash
# Builds the dem image (docker/Dockerfile) from the repository, labelled with
# the project's version (CMakeLists.txt), the git revision and the source.
#   bash docker/build.sh [build options...]      e.g. --pull=never --network host
#   bash docker/build.sh --deb FILE.deb [build options...]
#       the runtime image from a Debian package a host build made ((cd build
#       && cpack)), instead of compiling in the image's build stage: the
#       context is then a directory of the package and docker/experiment.sh
#       alone.
# DEM_IMAGE names the image (default: tagged dem:<version> and dem:latest;
# podman stores them as localhost/dem:...). CONTAINER_ENGINE picks podman or docker (default:
# podman when installed). podman builds in docker format, as the OCI image
# format has no HEALTHCHECK.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
engine="${CONTAINER_ENGINE:-$(command -v podman >/dev/null 2>&1 && echo podman || echo docker)}"

version=$(sed -n 's/^project(dem VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
[ -n "$version" ] || { echo "build.sh: no project version in $root/CMakeLists.txt" >&2; exit 1; }
revision=$(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)
source=$(git -C "$root" remote get-url origin 2>/dev/null || echo "file://$root")
tags=(--tag "${DEM_IMAGE:-dem:$version}")
[ -n "${DEM_IMAGE:-}" ] || tags+=(--tag dem:latest)

format=()
[ "$engine" = podman ] && format=(--format docker)
context="$root"
# Named even when it is the Dockerfile's default: buildah (podman 4.3) skips
# the stages it finds unused before it applies an ARG's default, and then
# takes `FROM ${DEM_PACKAGE}` for an image of that name.
package=(--build-arg DEM_PACKAGE=build)
if [ "${1:-}" = --deb ]; then
  deb="$(realpath "$2")"
  shift 2
  [ -f "$deb" ] || { echo "build.sh: no package $deb" >&2; exit 1; }
  context=$(mktemp -d)
  trap 'rm -rf "$context"' EXIT
  mkdir -p "$context/package" "$context/docker"
  cp "$deb" "$context/package/dem.deb"
  cp "$root/docker/experiment.sh" "$context/docker/"
  package=(--build-arg DEM_PACKAGE=context)
fi
"$engine" build "${format[@]}" --file "$root/docker/Dockerfile" "${tags[@]}" "${package[@]}" \
  --build-arg DEM_VERSION="$version" --build-arg DEM_REVISION="$revision" --build-arg DEM_SOURCE="$source" \
  "$@" "$context"
