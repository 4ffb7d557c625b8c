#!/usr/bin/env bash
# Renders the SVG icon to the 256 px PNG that the window, the .desktop file and the package use.
# Run after editing sightline.svg (needs rsvg-convert from librsvg2-bin); commit both files.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rsvg-convert -w 256 -h 256 "$here/sightline.svg" -o "$here/sightline.png"
