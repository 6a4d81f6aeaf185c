#!/usr/bin/env bash
# glTF 2.0 scenes through the command line (issue 13; scenes/README.md, "glTF 2.0 scenes"):
# - examples/scenes/gltf-normal-map renders on the CPU at low resolution and prints its mapping
#   warnings, each expected one checked and no other;
# - with `gpu` as the third argument, it renders on both backends at 16 spp and the images are
#   in lockstep (twinray compare --lockstep: at least 99% of the pixels within 1e-4 relative,
#   no systematic or clustered 4x4 window);
# - `twinray convert` writes it as XML that renders the same image bit for bit;
# - malformed files (truncated JSON, a missing buffer, a bad GLB header) exit 3 with one line
#   naming the file.
set -u
twinray=$1
example=$2
mode=${3:-cpu}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
scene=$example/scene.gltf

if [ "$mode" = gpu ]; then
  for backend in cpu gpu; do
    "$twinray" render "$scene" -D width=32 -D height=24 --spp 16 --seed 5 --backend $backend \
      -o "$work/$backend.exr" >/dev/null 2>"$work/$backend.err" ||
      { fail "$backend render: $(cat "$work/$backend.err")"; exit 1; }
  done
  if "$twinray" compare "$work/gpu.exr" "$work/cpu.exr" --lockstep >"$work/cmp" 2>&1; then
    echo "ok lockstep: $(grep 'lockstep ' "$work/cmp")"
  else
    fail "not in lockstep: $(cat "$work/cmp")"
  fi
  exit $((failures > 0))
fi

"$twinray" render "$scene" -D width=24 -D height=16 --spp 4 --seed 7 -o "$work/cpu.exr" \
  >/dev/null 2>"$work/err"
status=$?
[ $status -eq 0 ] || fail "render exit $status: $(cat "$work/err")"
expected=(
  "scene.gltf:208: samplers[0].minFilter: not used: twinray's path tracer integrates"
)
for w in "${expected[@]}"; do
  grep -Fq -- "warning: $scene${w#scene.gltf}" "$work/err" || fail "warning '$w' not printed"
done
printed=$(grep -c '^warning: ' "$work/err")
[ "$printed" -eq ${#expected[@]} ] || fail "$printed warnings, expected ${#expected[@]}: $(cat "$work/err")"
[ $failures -eq 0 ] && echo "ok render: ${#expected[@]} warnings"

# convert: the XML it writes renders the same image, bit for bit (same scene records, seed).
mkdir "$work/convert"
"$twinray" convert "$scene" -o "$work/convert/scene.xml" -D width=24 -D height=16 -D spp=4 \
  >/dev/null 2>"$work/convert.err" || fail "convert: $(cat "$work/convert.err")"
"$twinray" render "$work/convert/scene.xml" --seed 7 -o "$work/converted.exr" >/dev/null \
  2>"$work/converted.err" || fail "render of the converted XML: $(cat "$work/converted.err")"
if idiff -a -fail 0 -warn 0 "$work/cpu.exr" "$work/converted.exr" >"$work/idiff" 2>&1; then
  echo "ok convert: $(ls "$work/convert" | tr '\n' ' ')"
else
  fail "the converted XML renders another image: $(tail -3 "$work/idiff")"
fi
[ "$(ls "$work/convert" | grep -cv '^scene')" -eq 0 ] || fail "convert left other files: $(ls "$work/convert")"

# bad input: exit 3, one line "file:line: ..."
check_bad() {
  local file=$1 words=$2
  "$twinray" render "$file" -D width=8 -D height=8 --spp 1 -o "$work/bad.exr" >/dev/null 2>"$work/bad_err"
  local status=$?
  [ $status -eq 3 ] || { fail "$(basename "$file"): exit $status, expected 3: $(cat "$work/bad_err")"; return; }
  [ "$(wc -l <"$work/bad_err")" -eq 1 ] || fail "$(basename "$file"): not one line: $(cat "$work/bad_err")"
  grep -Fq -- "$file:" "$work/bad_err" || fail "$(basename "$file"): the file is not named: $(cat "$work/bad_err")"
  grep -Fq -- "$words" "$work/bad_err" || fail "$(basename "$file"): '$words' not in: $(cat "$work/bad_err")"
  echo "ok bad $(basename "$file")"
}
head -c 400 "$scene" >"$work/truncated.gltf"
check_bad "$work/truncated.gltf" "malformed JSON"
sed 's/"scene.bin"/"missing.bin"/' "$scene" >"$work/nobin.gltf"
check_bad "$work/nobin.gltf" "buffers[0].uri: file \"missing.bin\" not found"
printf 'glTF\002\000\000\000' >"$work/header.glb"
check_bad "$work/header.glb" "truncated GLB header"
exit $((failures > 0))
