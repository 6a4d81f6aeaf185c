#!/usr/bin/env bash
# --emitter-selection: the EXR metadata (twinray:emitter_selection) says which selection
# rendered the image, uniform (Mitsuba's) by default; an unknown one is a usage error (exit 2)
# that writes nothing.
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
twinray=$1
{
  echo '<scene version="3.0.0">'
  echo '  <emitter type="point"><point name="position" x="0" y="0" z="0"/></emitter>'
  echo '  <shape type="sphere"><transform name="to_world"><translate z="4"/></transform>'
  echo '    <emitter type="area"/></shape>'
  echo '  <sensor type="perspective"><sampler type="independent"><integer name="sample_count" value="2"/></sampler>'
  echo '    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>'
  echo '  </sensor></scene>'
} >"$dir/scene.xml"
for selection in default uniform power bvh; do
  args=()
  [ "$selection" = default ] || args=(--emitter-selection "$selection")
  "$twinray" render "$dir/scene.xml" -o "$dir/$selection.exr" "${args[@]}" >/dev/null
  expected=$selection
  [ "$selection" = default ] && expected=uniform
  meta=$(oiiotool --info -v "$dir/$selection.exr")
  echo "$meta" | grep -q "twinray:emitter_selection: \"$expected\"" ||
    { echo "$meta"; echo "$selection: twinray:emitter_selection is not $expected"; exit 1; }
done
status=0
"$twinray" render "$dir/scene.xml" -o "$dir/bad.exr" --emitter-selection nearest 2>"$dir/err.txt" ||
  status=$?
[ "$status" = 2 ] || { cat "$dir/err.txt"; echo "unknown selection: exit $status, expected 2"; exit 1; }
grep -q "uniform, power or bvh" "$dir/err.txt" || { cat "$dir/err.txt"; echo "no reason given"; exit 1; }
[ ! -e "$dir/bad.exr" ] || { echo "an output was written"; exit 1; }
