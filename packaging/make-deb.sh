#!/usr/bin/env bash
# Builds the Debian package build/packages/sightline_VERSION_ARCH.deb from the build folder:
# builds only what the package holds (the programs and their man pages; an up-to-date build
# folder builds nothing), then CPack installs them into a staging folder and dpkg-shlibdeps
# computes the dependencies. Prints the package's path on its last line.
# Usage: make-deb.sh [BUILD_DIR]   (default: build/, configured first when it does not exist)
#   SIGHTLINE_DEB_NO_BUILD=1: package the build folder as it is (the install test uses it).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
jobs="${SIGHTLINE_JOBS:-$(nproc)}"

for tool in cpack dpkg-deb dpkg-shlibdeps; do
  command -v "$tool" >/dev/null || {
    echo "make-deb.sh: $tool is missing (cmake, dpkg-dev: see packaging/install-deps.sh)" >&2
    exit 1
  }
done
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
if [ "${SIGHTLINE_DEB_NO_BUILD:-0}" != 1 ]; then
  targets="sightline sightline-cli"
  # sightline-node when the build has ROS (SIGHTLINE_WITH_ROS).
  grep -q '^SIGHTLINE_WITH_ROS:BOOL=ON' "$build/CMakeCache.txt" && targets="$targets sightline-node"
  # shellcheck disable=SC2086
  cmake --build "$build" --target $targets sightline_man_pages -j"$jobs"
fi
rm -f "$build"/packages/sightline_*.deb
(cd "$build" && cpack -G DEB -C Release >"$build/cpack.log" 2>&1) || {
  cat "$build/cpack.log" >&2
  echo "make-deb.sh: cpack failed (log above)" >&2
  exit 1
}
deb=$(ls "$build"/packages/sightline_*.deb)
echo "make-deb.sh: $(du -h "$deb" | cut -f1) package; install with: sudo apt install $deb"
echo "$deb"
