#!/usr/bin/env bash
# The Debian package as a user gets it: packages the existing build folder (packaging/make-deb.sh
# without rebuilding), unpacks it into a temporary root with dpkg -x, checks what it holds and
# what it depends on (dpkg-deb -I), then runs the installed programs from a folder outside the
# source tree: --version, `sightline-cli info` on real data and the GUI's --screenshot under Xvfb.
# Usage: deb_install_test.sh SOURCE_DIR BUILD_DIR DATA_DIR   (SIGHTLINE_DATA_DIR overrides DATA_DIR)
# Exit 77 (skipped) when the recorded data is absent.
set -uo pipefail
source_dir="$1"
build_dir="$2"
data_dir="${SIGHTLINE_DATA_DIR:-$3}"
status=0
fail() { echo "FAIL: $*"; status=1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1  # Outside the source tree: nothing may be found relative to it.

if ! SIGHTLINE_DEB_NO_BUILD=1 bash "$source_dir/packaging/make-deb.sh" "$build_dir" >make.log 2>&1
then
  cat make.log
  echo "FAIL: make-deb.sh failed"
  exit 1
fi
deb=$(tail -n 1 make.log)
version=$(sed -n 's/^project(Sightline VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")
arch=$(dpkg --print-architecture)
[ "$(basename "$deb")" = "sightline_${version}_${arch}.deb" ] ||
  fail "package is named $(basename "$deb"), expected sightline_${version}_${arch}.deb"
echo "package: $deb ($(du -k "$deb" | cut -f1) KiB)"

# Its control data: the dependencies dpkg-shlibdeps found, and what Qt loads at run time.
dpkg-deb -I "$deb" >info.txt || fail "dpkg-deb -I cannot read $deb"
depends=$(sed -n 's/^ Depends: //p' info.txt)
echo "Depends: $depends"
# One package name per line (alternatives "a | b" split too), versions dropped.
echo "$depends" | tr ',|' '\n\n' | sed 's/^ *//; s/ .*//' | sort -u >depends.txt
for needed in libc6 libstdc++6 libqt6widgets6 libqt6gui6 libqt6core6 libvtk9.1 \
              libopencv-core406 libyaml-cpp0.7 qt6-qpa-plugins; do
  grep -qxF "$needed" depends.txt || fail "Depends lacks $needed"
done
# A build with ROS ships sightline-node, which needs Debian's roscpp at run time.
with_ros=0
grep -q '^SIGHTLINE_WITH_ROS:BOOL=ON' "$build_dir/CMakeCache.txt" && with_ros=1
if [ "$with_ros" = 1 ]; then
  for needed in libroscpp4d librosbag-storage4d; do
    grep -qxF "$needed" depends.txt || fail "Depends lacks $needed (sightline-node)"
  done
fi
grep -E '^libqt5|-dev$' depends.txt && fail "Depends names Qt5 or a -dev package (above)"
grep -q '^ Installed-Size: ' info.txt || fail "no Installed-Size in the control data"

# Its files: the programs, man pages, desktop entry, icons, metainfo, translations; no tests.
dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|' >files.txt
for file in /usr/bin/sightline /usr/bin/sightline-cli /usr/libexec/sightline/sightline-cli-full \
            /usr/libexec/sightline/sightline-cli-stereo \
            /usr/share/man/man1/sightline.1.gz \
            /usr/share/man/man1/sightline-cli.1.gz /usr/share/applications/sightline.desktop \
            /usr/share/icons/hicolor/scalable/apps/sightline.svg \
            /usr/share/icons/hicolor/256x256/apps/sightline.png \
            /usr/share/metainfo/org.sightline.Sightline.metainfo.xml \
            /usr/share/doc/sightline/README.md; do
  grep -qx "$file" files.txt || fail "the package lacks $file"
done
for ts in "$source_dir"/translations/sightline_*.ts; do
  qm="/usr/share/sightline/translations/$(basename "${ts%.ts}").qm"
  grep -qx "$qm" files.txt || fail "the package lacks $qm"
done
if [ "$with_ros" = 1 ]; then
  for file in /usr/bin/sightline-node /usr/share/man/man1/sightline-node.1.gz; do
    grep -qx "$file" files.txt || fail "the package lacks $file"
  done
fi
grep -E '/(test_|bench_)[^/]*$|\.a$|/include/' files.txt && fail "test, benchmark or build files above"

mkdir root && dpkg -x "$deb" root || { echo "FAIL: dpkg -x failed"; exit 1; }
cli="$work/root/usr/bin/sightline-cli"
gui="$work/root/usr/bin/sightline"
unset QT_QPA_PLATFORM_PLUGIN_PATH QT_PLUGIN_PATH  # Qt finds its plugins as installed.

programs=("$cli" "$gui")
[ "$with_ros" = 1 ] && programs+=("$work/root/usr/bin/sightline-node")
for program in "${programs[@]}"; do
  out=$(QT_QPA_PLATFORM=offscreen "$program" --version 2>&1)
  echo "$out" | grep -Eq "$version \(commit [0-9a-f]{7,}" ||
    fail "$(basename "$program") --version printed '$out'"
done
# sightline-cli hands `run` to /usr/libexec/sightline/sightline-cli-full inside the installed tree.
"$cli" run --help >run-help.out 2>&1 || { cat run-help.out; fail "installed sightline-cli run --help failed"; }
grep -q '^usage: sightline-cli run PIPELINE' run-help.out ||
  { cat run-help.out; fail "installed sightline-cli run --help did not print the run usage"; }
zcat root/usr/share/man/man1/sightline-cli.1.gz | grep -q 'info PATH' ||
  fail "the sightline-cli man page lacks its commands"
zcat root/usr/share/man/man1/sightline.1.gz | grep -q '\\-\\-screenshot' ||
  fail "the sightline man page lacks its options"
if [ "$with_ros" = 1 ]; then
  zcat root/usr/share/man/man1/sightline-node.1.gz | grep -q '\\-\\-pipeline' ||
    fail "the sightline-node man page lacks its options"
fi
grep -q '^Exec=sightline' root/usr/share/applications/sightline.desktop ||
  fail "the desktop entry does not start sightline"
if command -v desktop-file-validate >/dev/null; then
  desktop-file-validate root/usr/share/applications/sightline.desktop || fail "desktop entry invalid"
fi

if [ ! -d "$data_dir/tum_fr1_desk" ]; then
  echo "SKIPPED: no recorded data at $data_dir (set SIGHTLINE_DATA_DIR)"
  [ "$status" -eq 0 ] && exit 77
  exit 1
fi
"$cli" info "$data_dir/tum_fr1_desk" >info.out 2>&1 || fail "installed sightline-cli info failed"
cat info.out
grep -q '^format: TUM RGB-D' info.out && grep -Eq '^frames: [1-9][0-9]* RGB-D frames' info.out &&
  grep -q '^ground truth: yes' info.out || fail "sightline-cli info did not describe tum_fr1_desk"

# `run stereo-vo` on a recorded stereo dataset runs in /usr/libexec/sightline/sightline-cli-stereo.
if [ -d "$data_dir/kitti_clip1" ]; then
  "$cli" run stereo-vo "$data_dir/kitti_clip1" --out "$work/vo" --quiet >vo.out 2>&1 ||
    { cat vo.out; fail "installed sightline-cli run stereo-vo failed"; }
  [ "$(grep -vc "^#" "$work/vo/trajectory.txt" 2>/dev/null)" = 51 ] ||
    fail "installed sightline-cli run stereo-vo wrote no 51-pose trajectory.txt"
fi

run_gui() {
  if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a -s "-screen 0 1280x800x24" "$@"; fi
}
run_gui env QT_QPA_PLATFORM=xcb "$gui" --open "$data_dir/tum_fr1_desk" --pipeline mapping \
  --frames 3 --timeout 240 --screenshot "$work/window.png" >gui.log 2>&1 ||
  { cat gui.log; fail "installed sightline --screenshot failed"; }
if [ -s "$work/window.png" ]; then
  size=$(python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); \
print(*struct.unpack('>II', d[16:24]))" "$work/window.png" 2>/dev/null || echo "?")
  echo "screenshot: $size px, $(du -k "$work/window.png" | cut -f1) KiB"
  [ "$(du -k "$work/window.png" | cut -f1)" -gt 20 ] || fail "the screenshot is nearly empty"
else
  fail "no screenshot written"
fi
[ "$status" -eq 0 ] && echo "OK: the package installs and its programs run outside the source tree"
exit "$status"
