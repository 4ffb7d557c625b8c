#!/usr/bin/env bash
# Runs clang-tidy (the root .clang-tidy) over the project's sources with build/'s compile
# commands; fails on any finding. Arguments limit it to files or folders (default: core app
# widgets). SIGHTLINE_JOBS sets the parallel runs (default: the number of cores).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
[ -f build/compile_commands.json ] || { echo "run-clang-tidy.sh: build/ is not configured" >&2; exit 1; }
paths=("$@")
[ ${#paths[@]} -gt 0 ] || paths=(core app widgets)
git ls-files "${paths[@]}" | grep '\.cpp$' |
  xargs -P "${SIGHTLINE_JOBS:-$(nproc)}" -n 4 clang-tidy -p build --quiet 2>/dev/null
