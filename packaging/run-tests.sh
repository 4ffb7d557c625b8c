#!/usr/bin/env bash
# The README's second command: install what is needed, build, and run every test with ctest.
# GUI tests need an X server: the whole run happens under Xvfb (Mesa llvmpipe OpenGL).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
bash packaging/install-deps.sh
start=$(date +%s)
bash packaging/build.sh
echo "run-tests.sh: build took $(( $(date +%s) - start )) s"
cd build
xvfb-run -a -s "-screen 0 1280x800x24" \
  ctest --output-on-failure --timeout 600 -j"${SIGHTLINE_JOBS:-$(nproc)}"
