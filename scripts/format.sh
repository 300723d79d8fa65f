#!/usr/bin/env bash
# Formats every C++ file in the repository with .clang-format (the house
# style: Google's, 120 columns), or with --check only reports the files
# that differ from it and exits 1 (the test code_format runs this).
#   scripts/format.sh [--check]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
format=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$format" ]; then
  echo "format.sh: clang-format is not installed (scripts/install_deps.sh installs it)" >&2
  exit 2
fi
# Tracked and new (not ignored) files when this is a git checkout; otherwise (a source archive) every C++ file.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.cpp' '*.h' '*.hpp' '*.cc')
else
  mapfile -t files < <(find . -path ./build -prune -o \( -name '*.cpp' -o -name '*.h' -o -name '*.hpp' -o -name '*.cc' \) -print)
fi
if [ "${1:-}" = --check ]; then
  differing=()
  for f in "${files[@]}"; do
    "$format" --dry-run --Werror "$f" >/dev/null 2>&1 || differing+=("$f")
  done
  if [ ${#differing[@]} -gt 0 ]; then
    echo "format.sh: ${#differing[@]} of ${#files[@]} files differ from .clang-format (scripts/format.sh fixes them):" >&2
    printf '  %s\n' "${differing[@]}" >&2
    exit 1
  fi
  echo "format.sh: ${#files[@]} files follow .clang-format"
else
  printf '%s\0' "${files[@]}" | xargs -0 "$format" -i
fi
