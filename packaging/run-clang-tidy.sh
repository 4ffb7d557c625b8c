#!/usr/bin/env bash
# Runs clang-tidy (the root .clang-tidy) over the project's sources with build/'s compile
# commands; fails on any finding. Arguments limit it to files or folders (default: core app
# widgets). SIGHTLINE_JOBS sets the parallel runs (default: the number of cores). GCC's
# precompiled headers are not readable by clang, so they are left out of the commands it gets.
# A whole-tree run takes about 1.5 h on 2 cores.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
[ -f build/compile_commands.json ] || { echo "run-clang-tidy.sh: build/ is not configured" >&2; exit 1; }
db="$(mktemp -d)"
trap 'rm -rf "$db"' EXIT
sed -E 's# -Winvalid-pch##g; s# -include [^ "]*cmake_pch\.hxx##g' build/compile_commands.json \
  >"$db/compile_commands.json"
paths=("$@")
[ ${#paths[@]} -gt 0 ] || paths=(core app widgets)
git ls-files "${paths[@]}" | grep '\.cpp$' |
  xargs -P "${SIGHTLINE_JOBS:-$(nproc)}" -n 4 clang-tidy -p "$db" --quiet 2>/dev/null
