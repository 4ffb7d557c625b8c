#!/usr/bin/env bash
# Fails if core/ includes a Qt header or if a core-only executable (sightline-cli and the
# sightline-cli-full and sightline-cli-stereo it hands commands to, the core tests) links any Qt library.
set -u
source_dir="$1"
bin_dir="$2"
status=0
hits=$(grep -rlE '#include *[<"](Q[A-Za-z]+|Qt[A-Za-z]*/)' "$source_dir/core" 2>/dev/null)
if [ -n "$hits" ]; then echo "FAIL: core/ includes Qt headers:"; echo "$hits"; status=1; fi
for exe in sightline-cli sightline-cli-full sightline-cli-stereo test_status test_option_set test_run_pipeline; do
  f="$bin_dir/$exe"
  if [ ! -x "$f" ]; then echo "FAIL: $f was not built"; status=1; continue; fi
  if ldd "$f" | grep -qE 'libQt[0-9]'; then
    echo "FAIL: $exe links Qt:"; ldd "$f" | grep -E 'libQt[0-9]'; status=1
  fi
done
[ $status -eq 0 ] && echo "core/ is Qt-free"
exit $status
