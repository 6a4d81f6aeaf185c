#!/usr/bin/env bash
# Bad scene files through the command line (issue 2): each must exit with status 3, print
# exactly one line "file:line: ..." naming the file, and leave no output file behind; an
# output file that existed before must be left untouched.
set -u
twinray=$1
dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for scene in "$dir"/*.xml; do
  name=$(basename "$scene" .xml)
  echo "previous render" >"$work/$name.exr"
  "$twinray" render "$scene" -o "$work/$name.exr" >"$work/out" 2>"$work/err"
  status=$?
  lines=$(wc -l <"$work/err")
  message=$(cat "$work/err")
  if [ "$status" -ne 3 ]; then echo "FAIL $name: exit status $status, expected 3 ($message)"; failures=$((failures + 1)); continue; fi
  if [ "$lines" -ne 1 ]; then echo "FAIL $name: $lines lines on stderr, expected 1"; failures=$((failures + 1)); continue; fi
  if ! grep -Eq "$(basename "$scene"):[0-9]+: " "$work/err"; then echo "FAIL $name: no file:line in '$message'"; failures=$((failures + 1)); continue; fi
  if [ "$(cat "$work/$name.exr")" != "previous render" ] || [ -e "$work/${name}_var.exr" ] || [ -e "$work/$name.png" ]; then
    echo "FAIL $name: output files were written or changed"; failures=$((failures + 1)); continue
  fi
  if ls "$work" | grep -q tmp; then echo "FAIL $name: temporary file left behind"; failures=$((failures + 1)); continue; fi
  echo "ok $name: $message"
done
exit $((failures > 0))
