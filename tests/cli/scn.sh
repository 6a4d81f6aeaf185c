#!/usr/bin/env bash
# .scn scenes through the command line (issue 13; scenes/README.md, ".scn scenes"):
# - the two seed scenes and tests/cli/scenes/scn/features.scn render on the CPU at low
#   resolution and print their mapping warnings (each expected warning checked);
# - `twinray convert` output loads back and renders bit-identically to the .scn at the same
#   seed (MSE 0, and lockstep);
# - bad input exits 3 with one line file:line naming the offending line; convert's usage
#   errors exit 2 and an unwritable output exits 5.
set -u
twinray=$1
seed_dir=$2
scene_dir=$3
bad_dir=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
size=(-D width=24 -D height=16)

# name, then the warnings (substrings of stderr) it must print
check_render() {
  local scene=$1 name
  name=$(basename "$scene" .scn)
  shift
  "$twinray" render "$scene" "${size[@]}" --spp 4 --seed 7 -o "$work/$name.exr" \
    >"$work/$name.out" 2>"$work/$name.err"
  local status=$?
  if [ $status -ne 0 ]; then fail "$name: render exit $status: $(cat "$work/$name.err")"; return; fi
  for w in "$@"; do
    grep -Fq -- "$w" "$work/$name.err" || fail "$name: warning '$w' not printed"
  done
  local expected=$#
  local printed
  printed=$(grep -c '^warning: ' "$work/$name.err")
  [ "$printed" -eq "$expected" ] || fail "$name: $printed warnings, expected $expected: $(cat "$work/$name.err")"
  # convert, render the XML at the same seed, compare
  mkdir -p "$work/xml_$name"
  "$twinray" convert "$scene" -o "$work/xml_$name/$name.xml" >/dev/null 2>"$work/$name.convert_err" ||
    { fail "$name: convert failed: $(cat "$work/$name.convert_err")"; return; }
  cmp -s <(grep '^warning: ' "$work/$name.err") "$work/$name.convert_err" ||
    fail "$name: convert printed other warnings than render"
  "$twinray" render "$work/xml_$name/$name.xml" "${size[@]}" --spp 4 --seed 7 \
    -o "$work/${name}_xml.exr" >/dev/null 2>"$work/${name}_xml.err" ||
    { fail "$name: the converted XML does not render: $(cat "$work/${name}_xml.err")"; return; }
  "$twinray" compare "$work/$name.exr" "$work/${name}_xml.exr" --lockstep >"$work/$name.cmp" 2>&1 ||
    fail "$name: converted XML not in lockstep: $(cat "$work/$name.cmp")"
  grep -Eq '^  MSE 0  ' "$work/$name.cmp" || fail "$name: converted XML not bit-identical: $(grep MSE "$work/$name.cmp")"
  echo "ok $name: rendered, $expected warnings, convert round trip identical"
}

check_render "$seed_dir/cornellbox_original.scn" \
  'cornellbox_original.scn:30: materials[5]: material "shortBox" is used by no entity and no usemtl group' \
  'cornellbox_original.scn:34: materials[6]: material "tallBox" is used by no entity and no usemtl group'
check_render "$seed_dir/cornellbox_sphere.scn"
check_render "$scene_dir/features.scn" \
  'features.scn:4: skybox: unknown field, ignored' \
  'features.scn:9: camera.antialiasing_radius: approximate: a tent filter' \
  'features.scn:15: materials[1].color: ignored: colortexture gives this parameter' \
  'features.scn:17: materials[1].roughness: ignored: roughnesstexture gives this parameter' \
  'features.scn:22: materials[1].subsurface: unsupported' \
  "features.scn:26: materials[1].normaltexture: approximate: read as Mitsuba's normalmap" \
  'features.scn:27: materials[1].shininess: unknown field, ignored' \
  'features.scn:31: materials[4]: material "unused" is used by no entity' \
  'features.scn:36: entities[0].file: usemtl "nomaterial" of features.obj has no .scn material' \
  'features.scn:38: entities[0].rotation: approximate: rotations about several axes' \
  'features.scn:43: entities[2].file: not a field of a sphere entity, ignored'

# -D overrides what the .scn sets: the film is 24x16
grep -q '24x16' "$work/features.out" || fail "features: -D width/height not applied"
"$twinray" render "$scene_dir/features.scn" -D frobnicate=1 -o "$work/d.exr" >/dev/null 2>&1
[ $? -eq 3 ] || fail "an unknown -D: expected exit 3"

# bad input: name and the line the error must name
for case in malformed:3 missing_obj:5 bad_type:5 corrupt_obj:4 color_range:4 unknown_type:4 \
  unknown_material:4 not_object:1 no_camera:1 nonuniform_sphere:4 missing_texture:4 \
  repeated_key:6 too_deep:2; do
  name=${case%%:*}
  line=${case##*:}
  for verb in render convert; do
    echo "previous" >"$work/$name.out.exr"
    if [ $verb = render ]; then
      "$twinray" render "$bad_dir/$name.scn" -o "$work/$name.out.exr" >/dev/null 2>"$work/err"
    else
      "$twinray" convert "$bad_dir/$name.scn" -o "$work/$name.xml" >/dev/null 2>"$work/err"
    fi
    status=$?
    message=$(cat "$work/err")
    [ $status -eq 3 ] || { fail "$verb $name: exit $status, expected 3 ($message)"; continue; }
    [ "$(wc -l <"$work/err")" -eq 1 ] || { fail "$verb $name: more than one line: $message"; continue; }
    grep -q "$name.scn:$line: " "$work/err" || { fail "$verb $name: expected $name.scn:$line: in '$message'"; continue; }
    [ "$(cat "$work/$name.out.exr")" = previous ] && [ ! -e "$work/$name.xml" ] ||
      { fail "$verb $name: output written"; continue; }
    echo "ok $verb $name: $message"
  done
done

# convert: usage errors exit 2, an unwritable output 5
"$twinray" convert "$scene_dir/features.scn" >/dev/null 2>&1
[ $? -eq 2 ] || fail "convert without -o: expected exit 2"
"$twinray" convert "$scene_dir/features.xml" -o "$work/f.xml" >/dev/null 2>&1
[ $? -eq 2 ] || fail "convert of a non-.scn file: expected exit 2"
"$twinray" convert "$scene_dir/features.scn" -o "$work/no/such/folder/f.xml" >/dev/null 2>"$work/err"
[ $? -eq 5 ] || fail "convert into a missing folder: expected exit 5 ($(cat "$work/err"))"
exit $((failures > 0))
