#!/usr/bin/env bash
# Fails when a translation falls behind the GUI sources: runs lupdate over app/sightline and
# widgets into a copy of the .ts and reports every text that is new or changed (untranslated),
# every entry no source uses any more (stale), and every lupdate warning (e.g. a class whose tr()
# would look its texts up under the wrong context).
# Usage: ts_up_to_date_test.sh LUPDATE SOURCE_DIR TS_FILE
# Exit 77 (skipped) when lupdate is missing: it comes with qt6-l10n-tools.
set -euo pipefail
lupdate="$1"
source_dir="$2"
ts_file="$3"

if [ ! -x "$lupdate" ]; then
  echo "SKIPPED: lupdate not found at $lupdate" \
       "(install qt6-l10n-tools, see packaging/install-deps.sh)"
  exit 77
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
copy="$work/$(basename "$ts_file")"
cp "$ts_file" "$copy"
# The same reading as `cmake --build build --target update_translations`, minus -no-obsolete so
# stale entries show up instead of vanishing.
if ! (cd "$source_dir" && "$lupdate" -I "$source_dir" app/sightline widgets -ts "$copy") \
    >"$work/log" 2>&1; then
  cat "$work/log"
  echo "FAIL: lupdate failed"
  exit 1
fi

status=0
if grep -E '\.(cpp|h):[0-9]+: ' "$work/log"; then
  echo "FAIL: lupdate warns about the sources (above)"
  status=1
fi

# One line per message: "<type>\t<context>\t<source>", the source's line breaks as \n.
awk '
  /<name>/ { sub(/.*<name>/, ""); sub(/<\/name>.*/, ""); context = $0 }
  /<source>/ { in_source = 1; text = "" }
  in_source {
    line = $0
    sub(/.*<source>/, "", line)
    if (line ~ /<\/source>/) { sub(/<\/source>.*/, "", line); in_source = 0 }
    text = text (text == "" ? "" : "\\n") line
  }
  /<translation/ {
    type = "finished"
    if ($0 ~ /type="unfinished"/) type = "unfinished"
    else if ($0 ~ /type="(vanished|obsolete)"/) type = "stale"
    else if ($0 ~ /<translation[^>]*\/>/ || $0 ~ /<translation[^>]*><\/translation>/) type = "empty"
    printf "%s\t%s\t%s\n", type, context, text
  }
' "$copy" >"$work/messages"

total=$(wc -l <"$work/messages")
for type in unfinished empty stale; do
  count=$(grep -c "^$type	" "$work/messages" || true)
  if [ "$count" -gt 0 ]; then
    case $type in
      unfinished) echo "FAIL: $count texts in the sources have no finished translation in $ts_file:" ;;
      empty) echo "FAIL: $count entries have an empty translation:" ;;
      stale) echo "FAIL: $count entries in $ts_file are no longer in the sources:" ;;
    esac
    grep "^$type	" "$work/messages" | cut -f2- | sed 's/^/  /'
    status=1
  fi
done
if [ "$status" -ne 0 ]; then
  echo "Refresh with: cmake --build build --target update_translations;" \
       "then translate in linguist."
  exit 1
fi
echo "OK: $total messages, all translated, none stale ($ts_file)"
