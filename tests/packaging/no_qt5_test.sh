#!/usr/bin/env bash
# Fails if any executable or shared library Sightline built links or would load a Qt5 library.
# (Debian's VTK Qt module, OpenCV highgui and PCL's CMake config all drag Qt5 in.)
set -u
bin_dir="$1"
checked=0
bad=0
for f in "$bin_dir"/*; do
  [ -f "$f" ] && [ -x "$f" ] || continue
  case "$f" in *.sh) continue ;; esac
  checked=$((checked + 1))
  if ldd "$f" 2>/dev/null | grep -q 'libQt5'; then
    echo "FAIL: $f loads Qt5:"; ldd "$f" | grep 'libQt5' | sed 's/^/    /'
    bad=$((bad + 1))
  fi
done
echo "checked $checked executables in $bin_dir, $bad load Qt5"
[ "$checked" -gt 0 ] || { echo "FAIL: no executables found"; exit 1; }
[ "$bad" -eq 0 ]
