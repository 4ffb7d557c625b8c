#!/usr/bin/env bash
# Writes a man page from a program's --help: the build runs it for sightline and sightline-cli so
# the pages never drift from the programs. The help text goes in as it is printed (preformatted),
# with troff's special characters escaped.
# Usage: help-to-man.sh PROGRAM NAME "ONE-LINE SUMMARY" VERSION OUT_FILE
set -euo pipefail
program="$1"
name="$2"
summary="$3"
version="$4"
out="$5"

# The GUI prints its help without a display too (main.cpp picks the offscreen platform).
# Qt's warnings (stderr) stay out; "Usage: /path/to/build/bin/sightline" names the program.
help=$(QT_QPA_PLATFORM=offscreen "$program" --help 2>/dev/null | sed "s|$program|$name|g")
[ -n "$help" ] || { echo "help-to-man.sh: $program --help printed nothing" >&2; exit 1; }
escape() { sed -e 's/\\/\\e/g' -e "s/^\([.']\)/\\\\\&\1/" -e 's/-/\\-/g'; }
upper=$(echo "$name" | tr '[:lower:]' '[:upper:]')
{
  echo ".TH $upper 1 \"\" \"Sightline $version\" \"User Commands\""
  echo ".SH NAME"
  echo "$name \\- $(echo "$summary" | escape)"
  echo ".SH DESCRIPTION"
  echo "The text below is what \\fB$name \\-\\-help\\fR prints."
  echo ".PP"
  echo ".nf"
  echo "$help" | escape
  echo ".fi"
  echo ".SH FILES"
  echo "Recorded data sets are folders (TUM RGB\\-D, EuRoC, KITTI, image folders) or .oni files;"
  echo "see /usr/share/doc/sightline/README.md."
  echo ".SH SEE ALSO"
  if [ "$name" = sightline ]; then echo "\\fBsightline\\-cli\\fR(1)"; else echo "\\fBsightline\\fR(1)"; fi
} >"$out.tmp"
mv "$out.tmp" "$out"
