#!/usr/bin/env bash
# A stratified sampler's sample_count, and --spp, are rounded as Mitsuba rounds them; the render
# summary and the EXR metadata (twinray:spp, twinray:sample_count_rounding) say so.
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
twinray=$1
{
  echo '<scene version="3.0.0"><emitter type="constant"/>'
  echo '  <shape type="sphere"><transform name="to_world"><translate z="4"/></transform></shape>'
  echo '  <sensor type="perspective"><sampler type="stratified">'
  echo '    <integer name="sample_count" value="10"/></sampler>'
  echo '    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>'
  echo '  </sensor></scene>'
} >"$dir/scene.xml"
"$twinray" render "$dir/scene.xml" -o "$dir/a.exr" >"$dir/a.txt"
grep -q '^twinray: 8x8, 16 spp' "$dir/a.txt" || { cat "$dir/a.txt"; echo "expected 16 spp"; exit 1; }
grep -q '^twinray: stratified: sample_count 10 rounded up to 16, as Mitsuba$' "$dir/a.txt" ||
  { cat "$dir/a.txt"; echo "no rounding line"; exit 1; }
meta=$(oiiotool --info -v "$dir/a.exr")
echo "$meta" | grep -q 'twinray:spp: "16"' || { echo "$meta"; echo "twinray:spp not 16"; exit 1; }
echo "$meta" | grep -q 'twinray:sampler: "stratified"' || { echo "$meta"; echo "no twinray:sampler"; exit 1; }
echo "$meta" | grep -q 'twinray:sample_count_rounding: "stratified: sample_count 10 rounded up to 16, as Mitsuba"' ||
  { echo "$meta"; echo "no twinray:sample_count_rounding"; exit 1; }
"$twinray" render "$dir/scene.xml" -o "$dir/b.exr" --spp 5 >"$dir/b.txt"
grep -q '^twinray: 8x8, 9 spp' "$dir/b.txt" || { cat "$dir/b.txt"; echo "--spp 5: expected 9 spp"; exit 1; }
grep -q '^twinray: stratified: sample_count 5 rounded up to 9, as Mitsuba$' "$dir/b.txt" ||
  { cat "$dir/b.txt"; echo "--spp 5: no rounding line"; exit 1; }
"$twinray" render "$dir/scene.xml" -o "$dir/c.exr" --spp 25 >"$dir/c.txt"
if grep -q 'rounded' "$dir/c.txt"; then cat "$dir/c.txt"; echo "--spp 25 is a square"; exit 1; fi
echo ok
