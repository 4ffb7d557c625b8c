#!/usr/bin/env bash
# The README's first command: install what is needed, build, and launch the GUI.
# Without a display (a headless machine) it runs the GUI under Xvfb, saves a screenshot to
# build/sightline-window.png and says so.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
bash packaging/install-deps.sh
bash packaging/build.sh
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec build/bin/sightline "$@"
fi
echo "run-gui.sh: no display found; running the GUI under Xvfb and saving a screenshot instead."
data="${SIGHTLINE_DATA_DIR:-$here/../shared/data}/tum_fr1_desk"
args=("$@")
if [ ${#args[@]} -eq 0 ] && [ -d "$data" ]; then args=(--open "$data"); fi
if [ ${#args[@]} -gt 0 ]; then
  xvfb-run -a -s "-screen 0 1400x900x24" build/bin/sightline "${args[@]}" \
    --screenshot build/sightline-window.png --frames 5
else
  echo "run-gui.sh: no dataset to open; pass --open PATH"
fi
