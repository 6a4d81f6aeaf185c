#!/usr/bin/env bash
# `twinray conformance FOLDER`: one line a scene (rendered / out-of-scope / FAILED
# with the plugin or message), the counts, exit 1 when a scene FAILED, previews written.
set -eu
twinray=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir "$dir/scenes" "$dir/previews"
scene() {  # NAME BODY [SAMPLER]: a 4x4 scene around BODY; $spp is used as Mitsuba's doc scenes use it
  cat > "$dir/scenes/$1.xml" <<XML
<scene version="3.0.0">
  <default name="spp" value="64"/>
  <sensor type="perspective">
    <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/></film>
    <sampler type="${3:-independent}"><integer name="sample_count" value="\$spp"/></sampler>
  </sensor>
  $2
</scene>
XML
}
scene a_good '<shape type="sphere"><transform name="to_world"><translate z="4"/></transform></shape><emitter type="constant"/>'
scene b_hair '<shape type="sphere"><bsdf type="hair"/></shape>'
scene c_unimplemented '<shape type="sphere"><bsdf type="principledthin"/></shape>'
scene d_typo '<shape type="sphere"><float name="radiuss" value="1"/></shape>'

status=0
"$twinray" conformance "$dir/scenes" --spp 2 --previews "$dir/previews" >"$dir/out.txt" || status=$?
cat "$dir/out.txt"
[ "$status" -eq 1 ] || { echo "expected exit 1 with a FAILED scene, got $status"; exit 1; }
expect() { grep -q -- "$1" "$dir/out.txt" || { echo "missing line: $1"; exit 1; }; }
expect '^rendered  *a_good.xml'
expect '^out-of-scope  *b_hair.xml .*not supported by twinray: hair (out of scope'
expect '^FAILED  *c_unimplemented.xml .*not supported by twinray: principledthin (not implemented'
expect "^FAILED  *d_typo.xml .*d_typo.xml:7: unused parameter 'radiuss'"
expect '^4 scenes: 1 rendered, 1 out-of-scope, 2 FAILED$'
[ -s "$dir/previews/a_good.png" ] || { echo "no preview for the rendered scene"; exit 1; }
[ "$(ls "$dir/previews")" = "a_good.png" ] || { echo "previews for scenes that did not render"; exit 1; }

rm "$dir/scenes/c_unimplemented.xml" "$dir/scenes/d_typo.xml"
"$twinray" conformance "$dir/scenes" >/dev/null || { echo "expected exit 0 without FAILED scenes"; exit 1; }
status=0
"$twinray" conformance "$dir/nowhere" 2>/dev/null || status=$?
[ "$status" -eq 2 ] || { echo "expected exit 2 for a missing folder, got $status"; exit 1; }
echo ok
