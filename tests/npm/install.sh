#!/usr/bin/env bash
# Installs the npm packages the independent-reader tests use (package.json,
# pinned by package-lock.json) into BUILD_DIR, with the test scripts beside
# them so Node resolves the packages from there. `npm ci` runs only when the
# lock file changed since the last install; the source tree stays clean.
#   install.sh BUILD_DIR
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
target="$1"
mkdir -p "$target"
cp "$here"/package.json "$here"/package-lock.json "$here"/*.mjs "$target"/
if ! command -v npm >/dev/null; then
  echo "install.sh: npm is missing (scripts/install_deps.sh installs Debian's nodejs and npm)" >&2
  exit 1
fi
stamp="$target/node_modules/.installed-lock"
if [ -f "$stamp" ] && cmp -s "$stamp" "$target/package-lock.json"; then
  exit 0
fi
(cd "$target" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
cp "$target/package-lock.json" "$stamp"
