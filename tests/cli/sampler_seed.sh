#!/usr/bin/env bash
# The sampler's `seed` is the render's seed unless --seed overrides it (Mitsuba semantics):
# a scene with seed 5 renders bit-identically to --seed 5 and differently from --seed 0.
set -eu
twinray=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat > "$dir/scene.xml" <<'XML'
<scene version="3.0.0">
  <sensor type="perspective">
    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
    <sampler type="independent"><integer name="sample_count" value="4"/>
      <integer name="seed" value="5"/></sampler>
  </sensor>
  <shape type="sphere"><transform name="to_world"><translate z="4"/></transform></shape>
  <emitter type="constant"/>
</scene>
XML
"$twinray" render "$dir/scene.xml" -o "$dir/scene_seed.exr" >/dev/null
"$twinray" render "$dir/scene.xml" -o "$dir/flag_seed.exr" --seed 5 >/dev/null
"$twinray" render "$dir/scene.xml" -o "$dir/other_seed.exr" --seed 0 >/dev/null
pixels() {
  local p
  p=$(oiiotool --dumpdata "$1" | grep Pixel)
  [ -n "$p" ] || { echo "no pixels read from $1" >&2; exit 1; }
  echo "$p"
}
[ "$(pixels "$dir/scene_seed.exr")" = "$(pixels "$dir/flag_seed.exr")" ] ||
  { echo "the scene's seed 5 and --seed 5 rendered different images"; exit 1; }
[ "$(pixels "$dir/scene_seed.exr")" != "$(pixels "$dir/other_seed.exr")" ] ||
  { echo "--seed 0 rendered the same image as seed 5"; exit 1; }
echo ok
