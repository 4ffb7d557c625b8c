#!/usr/bin/env bash
# The README's first command: install what is needed, build, and launch the GUI on the built-in
# demo (simulated recordings, generated once into ~/.cache/sightline). Arguments replace --demo,
# e.g. `run-gui.sh --open ../shared/data/tum_fr1_desk`.
# Without a display (a headless machine) it runs the GUI under Xvfb, saves a screenshot to
# build/sightline-window.png and says so.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
bash packaging/install-deps.sh
bash packaging/build.sh
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--demo)
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec build/bin/sightline "${args[@]}"
fi
echo "run-gui.sh: no display found; running the GUI under Xvfb and saving a screenshot instead."
xvfb-run -a -s "-screen 0 1400x900x24" build/bin/sightline "${args[@]}" \
  --screenshot build/sightline-window.png --frames 30 --timeout 900
echo "run-gui.sh: see build/sightline-window.png"
