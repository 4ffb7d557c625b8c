#!/usr/bin/env bash
# Configures and builds Sightline (Release) into build/. Extra arguments go to cmake configure.
# A new build dir uses Ninja (one graph for the whole build: no per-directory make recursion);
# an existing one keeps the generator it has.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
jobs="${SIGHTLINE_JOBS:-$(nproc)}"
generator=()
if [ ! -f build/CMakeCache.txt ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j"$jobs"
