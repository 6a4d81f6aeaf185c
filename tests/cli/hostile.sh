#!/usr/bin/env bash
# Hostile inputs through the command line (issue 12): a table of cases, each with the exit
# status and the message (an extended regular expression) it must give. Every refused render
# leaves no output file and an existing one untouched; nothing crashes (a status above 8 or a
# signal fails the case). usage: hostile.sh TWINRAY
set -u
export LC_ALL=C
twinray=$1
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
failures=0 cases=0

# --- inputs ------------------------------------------------------------------------------
# glTF: a lit triangle seen by a camera, one field replaced by each case (gltf NAME SED_EXPR).
gltf() {
  sed "$2" >"$d/$1.gltf" <<'EOF'
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
 "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 2]}],
 "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
 "materials": [{"emissiveFactor": [1, 1, 1]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}
EOF
}
gltf gltf_ok 's/x/x/'
gltf gltf_count_beyond_view 's/"count": 3/"count": 4/'
gltf gltf_view_beyond_buffer 's/"buffer": 0, "byteLength": 36/"buffer": 0, "byteLength": 360/'
gltf gltf_bad_index 's/"POSITION": 0/"POSITION": 7/'
gltf gltf_bad_component 's/5126/5124/'
gltf gltf_bad_base64 's/AAAAAAAAAAAA/AA!AAAAAAAAA/'
gltf gltf_missing_bin 's|"uri": "data:[^"]*"|"uri": "missing.bin"|'
gltf gltf_required_extension 's/"asset"/"extensionsRequired": ["KHR_draco_mesh_compression"], "asset"/'
gltf gltf_negative_ior 's/"materials": \[{/"materials": [{"extensions": {"KHR_materials_ior": {"ior": 0.5}}, /'
gltf gltf_blend 's/"materials": \[{/"materials": [{"alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.5]}, /'
gltf gltf_no_camera 's/"nodes": \[0, 1\]/"nodes": [0]/'
gltf gltf_tangent_vec3 's/"POSITION": 0}/"POSITION": 0, "NORMAL": 0, "TANGENT": 0}/'
{ printf 'glTF\002\000\000\000\100\000\000\000'; head -c 40 /dev/zero; } >"$d/gltf_bad_length.glb"

scene() {  # scene NAME BODY: a scene file d/NAME.xml with a working sensor around BODY
  cat >"$d/$1.xml" <<EOF
<scene version="3.0.0">
  <sensor type="perspective">
    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
    <sampler type="independent"><integer name="sample_count" value="2"/></sampler>
  </sensor>
$2
</scene>
EOF
}
lit() { scene "$1" "<emitter type=\"constant\"/>
$2"; }
mesh() { echo "<shape type=\"$1\"><string name=\"filename\" value=\"$2\"/></shape>"; }

lit ok '<shape type="sphere"/>'
head -c 150 "$d/ok.xml" >"$d/truncated.xml"
sed 's#</sensor>#</film>#' "$d/ok.xml" >"$d/mismatched.xml"
head -c 4096 /dev/urandom >"$d/binary.xml"
: >"$d/empty.xml"
printf '<scene version="3.0.0">' >"$d/unclosed.xml"
lit unknown_plugin '<shape type="sphere"><bsdf type="velvet"/></shape>'
lit unknown_parameter '<shape type="sphere"><bsdf type="diffuse"><float name="glossiness" value="1"/></bsdf></shape>'
lit wrong_type '<shape type="sphere"><bsdf type="diffuse"><string name="reflectance" value="red"/></bsdf></shape>'
lit bad_float '<shape type="sphere"><float name="radius" value="abc"/></shape>'
lit bad_integer '<shape type="sphere"/><integrator type="path"><integer name="max_depth" value="2.5"/></integrator>'
lit huge_integer '<shape type="sphere"/><integrator type="path"><integer name="max_depth" value="99999999999999999999"/></integrator>'
lit aov_unknown_type '<shape type="sphere"/><integrator type="aov"><string name="aovs" value="dd:depth,vv:velocity"/></integrator>'
lit aov_bad_list '<shape type="sphere"/><integrator type="aov"><string name="aovs" value="dd:depth;nn:sh_normal"/></integrator>'
lit undefined_default '<shape type="sphere"><float name="radius" value="$size"/></shape>'
lit missing_include '<include filename="nowhere.xml"/>'
echo '<scene version="3.0.0"><include filename="cycle_b.xml"/></scene>' >"$d/cycle_a.xml"
echo '<scene version="3.0.0"><include filename="cycle_a.xml"/></scene>' >"$d/cycle_b.xml"
lit include_cycle '<include filename="cycle_a.xml"/>'
lit unknown_ref '<shape type="sphere"><ref id="nothing"/></shape>'
lit duplicate_id '<bsdf type="diffuse" id="a"/><bsdf type="diffuse" id="a"/><shape type="sphere"><ref id="a"/></shape>'
lit bad_version '<shape type="sphere"/>'
sed -i 's/version="3.0.0"/version="banana"/' "$d/bad_version.xml"
lit old_version '<shape type="sphere"/><integrator type="path"><integer name="maxDepth" value="3"/></integrator>'
sed -i 's/version="3.0.0"/version="0.6.0"/' "$d/old_version.xml"
# Bitterli's Mitsuba 0.6 style, read beyond Mitsuba 3.8's upgrade (scenes/xml_upgrade_beyond.h);
# the same text as version 2.0.0 is refused as Mitsuba 3.8 refuses it.
cat >"$d/ldrfilm_0_6.xml" <<'EOF'
<scene version="0.6.0">
  <integrator type="path"><boolean name="strictNormals" value="true"/></integrator>
  <sensor type="perspective">
    <transform name="toWorld"><lookAt origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <film type="ldrfilm"><integer name="width" value="8"/><integer name="height" value="8"/>
      <string name="fileFormat" value="png"/><float name="gamma" value="2.2"/></film>
    <sampler type="independent"><integer name="sampleCount" value="2"/></sampler>
  </sensor>
  <emitter type="constant"/>
  <shape type="sphere"/>
</scene>
EOF
sed 's/version="0.6.0"/version="2.0.0"/' "$d/ldrfilm_0_6.xml" >"$d/ldrfilm_2_0.xml"
for v in 0.6 0.6.0.0 99999999999999999999.0.0 4.0.0; do
  lit "version_$v" '<shape type="sphere"/>'
  sed -i "s/version=\"3.0.0\"/version=\"$v\"/" "$d/version_$v.xml"
done
lit missing_obj "$(mesh obj missing.obj)"
: >"$d/empty.obj"
lit empty_obj "$(mesh obj empty.obj)"
head -c 2048 /dev/urandom >"$d/garbage.obj"
lit garbage_obj "$(mesh obj garbage.obj)"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$d/bad_index.obj"
lit bad_index_obj "$(mesh obj bad_index.obj)"
printf 'v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$d/nan_vertex.obj"
lit nan_vertex_obj "$(mesh obj nan_vertex.obj)"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf 4 5 6\n' >"$d/zero_area.obj"
lit zero_area_obj "$(mesh obj zero_area.obj)"
# Found by CI's scripts/fuzz when Assimp read OBJ files: relative (negative) face indices.
printf '\nf -1//1/-4/rrrrrrrr/to/\n' >"$d/relative_index.obj"
lit relative_index_obj "$(mesh obj relative_index.obj)"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n' >"$d/corner_without_uv.obj"
lit corner_without_uv_obj "$(mesh obj corner_without_uv.obj)"
{ printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n# '; head -c 1100 /dev/zero | tr '\0' x; printf '\nf 1 2 3\n'; } >"$d/long_line.obj"
lit long_line_obj "$(mesh obj long_line.obj)"
lit missing_ply "$(mesh ply missing.ply)"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n' >"$d/truncated.ply"
head -c 20 /dev/urandom >>"$d/truncated.ply"
lit truncated_ply "$(mesh ply truncated.ply)"
printf 'ply\nformat ascii 1.0\nelement vertex banana\nend_header\n' >"$d/bad_header.ply"
lit bad_header_ply "$(mesh ply bad_header.ply)"
ply_ascii() {  # ply_ascii NAME LAST_FACE_LINE
  printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 3\n1 0 3\n0 1 3\n%s\n' "$2" >"$d/$1.ply"
  lit "$1_ply" "$(mesh ply "$1.ply")"
}
ply_ascii good_ascii '3 0 1 2'
lit vertex_tangents_missing '<shape type="ply"><string name="filename" value="good_ascii.ply"/>
<boolean name="vertex_tangents" value="true"/></shape>'
# Found by scripts/fuzz (Assimp, which read PLY files then, crashed on it): no x, y, z.
printf 'ply\nformat ascii 1.0\nelement vertex 2\nproperty float v\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n1\n0\n3 0 1 1\n' >"$d/no_xyz.ply"
lit no_xyz_ply "$(mesh ply no_xyz.ply)"
ply_ascii index_ascii '3 0 1 7'
ply_ascii short_ascii '3 0 1'
ply_ascii two_corner_face '2 0 1'  # found by scripts/fuzz (Assimp aborted on it)
texture() { lit "$1" "<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture name=\"reflectance\" type=\"bitmap\"><string name=\"filename\" value=\"$2\"/></texture></bsdf></shape>"; }
texture missing_image missing.png
: >"$d/empty.png"
texture empty_image empty.png
{ printf '\x89PNG\r\n\x1a\n'; head -c 500 /dev/urandom; } >"$d/corrupt.png"
texture corrupt_image corrupt.png
mkdir "$d/folder.png"
texture folder_image folder.png
# Found by scripts/fuzz: a BMP header claiming 2 x 100663298 texels (an allocation of gigabytes).
printf '\x42\x4d\x46\x00\x00\x00\x00\x00\x00\x00\x36\x00\x00\x00\x28\x00\x00\x00\x02\x00\x00\x00\x02\x00\x00\x06\x01\x00\x18\x00\x00\x00\x00\x00\x04\x00\x00\x09\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\xff\xff\xff\x00\x00\x00\x00\x00\x00\x00\x00\xff\xff\xff\x00\x00' >"$d/huge.bmp"
texture huge_image huge.bmp
# Found by scripts/fuzz: a PPM header claiming 303 x 65534 texels in a file of a few bytes.
printf 'P6\n303\n65534\n255\n\x00\x00\x0b\xb8' >"$d/short.ppm"
texture short_image short.ppm
lit nan_radius '<shape type="sphere"><float name="radius" value="nan"/></shape>'
lit inf_translate '<shape type="sphere"><transform name="to_world"><translate x="inf"/></transform></shape>'
scene nan_radiance '<shape type="sphere"/><emitter type="constant"><rgb name="radiance" value="nan, 1, 1"/></emitter>'
scene negative_radiance '<shape type="sphere"/><emitter type="constant"><rgb name="radiance" value="-1, 1, 1"/></emitter>'
lit negative_reflectance '<shape type="sphere"><bsdf type="diffuse"><rgb name="reflectance" value="-0.5"/></bsdf></shape>'
lit blend_no_weight '<shape type="sphere"><bsdf type="blendbsdf"><bsdf type="diffuse"/><bsdf type="conductor"/></bsdf></shape>'
lit blend_one_child '<shape type="sphere"><bsdf type="blendbsdf"><float name="weight" value="0.5"/><bsdf type="diffuse"/></bsdf></shape>'
lit normalmap_no_texture '<shape type="sphere"><bsdf type="normalmap"><bsdf type="diffuse"/></bsdf></shape>'
lit normalmap_in_blend '<shape type="sphere"><bsdf type="blendbsdf"><float name="weight" value="0.5"/><bsdf type="normalmap"><rgb name="normalmap" value="0.5, 0.5, 1"/><bsdf type="diffuse"/></bsdf><bsdf type="diffuse"/></bsdf></shape>'
lit zero_width '<shape type="sphere"/>'
sed -i 's/name="width" value="8"/name="width" value="0"/' "$d/zero_width.xml"
lit overflow_size '<shape type="sphere"/>'
sed -i 's/value="8"/value="4000000000"/g' "$d/overflow_size.xml"
lit huge_size '<shape type="sphere"/>'
sed -i 's/value="8"/value="60000"/g' "$d/huge_size.xml"
lit negative_spp '<shape type="sphere"/>'
sed -i 's/name="sample_count" value="2"/name="sample_count" value="-4"/' "$d/negative_spp.xml"
lit stratified_ok '<shape type="sphere"/>'
sed -i 's/type="independent"/type="stratified"/' "$d/stratified_ok.xml"
lit stratified_huge_spp '<shape type="sphere"/>'
sed -i 's/type="independent"><integer name="sample_count" value="2"/type="stratified"><integer name="sample_count" value="20000000"/' "$d/stratified_huge_spp.xml"
scene empty_scene ''
scene no_emitter '<shape type="sphere"/>'
echo '<scene version="3.0.0"/>' >"$d/bare.xml"
mkdir -p "$d/readonly"

# --- the table -------------------------------------------------------------------------
# check NAME EXPECTED_STATUS MESSAGE_REGEX -- twinray arguments
check() {
  local name=$1 want=$2 regex=$3
  shift 4
  cases=$((cases + 1))
  rm -rf "$d/out" && mkdir "$d/out" && echo "previous render" >"$d/out/img.exr"
  timeout 120 "$twinray" "$@" >"$d/stdout" 2>"$d/stderr"
  local status=$?
  local msg
  msg=$(head -c 400 "$d/stderr" | head -n 3)
  if [ "$status" != "$want" ]; then
    echo "FAIL $name: exit $status, expected $want: $msg"; failures=$((failures + 1)); return
  fi
  if ! grep -Eq -- "$regex" "$d/stderr" "$d/stdout"; then
    echo "FAIL $name: message does not match /$regex/: $msg"; failures=$((failures + 1)); return
  fi
  if [ "$want" != 0 ] && [ "$want" != 7 ]; then
    if [ "$(cat "$d/out/img.exr")" != "previous render" ] || [ -e "$d/out/img_var.exr" ] ||
      [ -e "$d/out/img.png" ] || [ "$(ls "$d/out" | wc -l)" != 1 ]; then
      echo "FAIL $name: output files were written or changed"; failures=$((failures + 1)); return
    fi
  fi
  echo "ok   $name ($status): ${msg:-$(tail -n 1 "$d/stdout")}"
}
r() { echo render "$d/$1.xml" -o "$d/out/img.exr"; }

check truncated_xml 3 'truncated\.xml:[0-9]+: ' -- $(r truncated)
check mismatched_tags 3 'mismatched\.xml:[0-9]+: ' -- $(r mismatched)
check binary_file 3 'binary\.xml:[0-9]+: ' -- $(r binary)
check empty_file 3 'empty\.xml:[0-9]+: ' -- $(r empty)
check unclosed_scene 3 'unclosed\.xml:[0-9]+: ' -- $(r unclosed)
check unknown_plugin 3 'unknown_plugin\.xml:[0-9]+: .*velvet' -- $(r unknown_plugin)
check unknown_parameter 3 'unknown_parameter\.xml:[0-9]+: .*glossiness' -- $(r unknown_parameter)
check wrong_value_type 3 'wrong_type\.xml:[0-9]+: .*reflectance' -- $(r wrong_type)
check bad_float 3 'bad_float\.xml:[0-9]+: .*abc' -- $(r bad_float)
check bad_integer 3 'bad_integer\.xml:[0-9]+: .*2\.5' -- $(r bad_integer)
check huge_integer 3 'huge_integer\.xml:[0-9]+: .*max_depth' -- $(r huge_integer)
check aov_unknown_type 3 'aov_unknown_type\.xml:[0-9]+: .*invalid AOV type "velocity"' -- $(r aov_unknown_type)
check aov_bad_list 3 'aov_bad_list\.xml:[0-9]+: .*invalid AOV "dd:depth;nn:sh_normal"' -- $(r aov_bad_list)
check undefined_default 3 'undefined_default\.xml:[0-9]+: .*size' -- $(r undefined_default)
check missing_include 3 'missing_include\.xml:[0-9]+: .*nowhere\.xml' -- $(r missing_include)
check include_cycle 3 'cycle_.\.xml:[0-9]+: .*(cycle|recurs|itself)' -- $(r include_cycle)
check unknown_ref 3 'unknown_ref\.xml:[0-9]+: .*nothing' -- $(r unknown_ref)
check duplicate_id 3 'duplicate_id\.xml:[0-9]+: .*"?a"?' -- $(r duplicate_id)
check bad_version 3 'bad_version\.xml:[0-9]+: .*version' -- $(r bad_version)
check mitsuba_0_scene_upgraded 0 'old_version\.xml:[0-9]+: scene version 0\.[0-9.]+ upgraded on load' -- $(r old_version)
check mitsuba_0_ldrfilm_lookat 0 'ldrfilm_0_6\.xml:[0-9]+: beyond Mitsuba 3\.8.s upgrade.*ldrfilm.*file_format "png", gamma 2\.2' -- $(r ldrfilm_0_6)
check mitsuba_3_refuses_lookAt 3 'ldrfilm_2_0\.xml:4: unknown transform operation <lookAt>' -- $(r ldrfilm_2_0)
check two_part_version 3 'version_0\.6\.xml:[0-9]+: .*three period-separated numbers' -- $(r version_0.6)
check four_part_version 3 'version_0\.6\.0\.0\.xml:[0-9]+: .*three period-separated numbers' -- $(r version_0.6.0.0)
check huge_version 3 'version_9+\.0\.0\.xml:[0-9]+: .*after Mitsuba 3' -- $(r version_99999999999999999999.0.0)
check future_version 3 'version_4\.0\.0\.xml:[0-9]+: .*after Mitsuba 3' -- $(r version_4.0.0)
check missing_obj 3 'missing_obj\.xml:[0-9]+: .*missing\.obj' -- $(r missing_obj)
check empty_obj 3 'empty_obj\.xml:[0-9]+: .*empty\.obj' -- $(r empty_obj)
check garbage_obj 3 'garbage_obj\.xml:[0-9]+: .*garbage\.obj' -- $(r garbage_obj)
check obj_index_out_of_range 3 'bad_index_obj\.xml:[0-9]+: .*bad_index\.obj' -- $(r bad_index_obj)
check obj_nan_vertex 3 'nan_vertex_obj\.xml:[0-9]+: .*nan_vertex\.obj' -- $(r nan_vertex_obj)
check obj_relative_index 3 'relative_index_obj\.xml:[0-9]+: .*relative_index\.obj: line 2: relative face index -1' -- $(r relative_index_obj)
check obj_corner_without_uv 3 'corner_without_uv\.obj: line 5: a face corner without a texture coordinate' -- $(r corner_without_uv_obj)
check obj_long_line 3 'long_line\.obj: line 4: a line of 1102 characters' -- $(r long_line_obj)
check obj_zero_area_triangles 0 'twinray: 8x8' -- $(r zero_area_obj)
check missing_ply 3 'missing_ply\.xml:[0-9]+: .*missing\.ply' -- $(r missing_ply)
check truncated_ply 3 'truncated_ply\.xml:[0-9]+: .*truncated\.ply' -- $(r truncated_ply)
check ply_ascii_loads 0 'twinray: 8x8' -- $(r good_ascii_ply)
check vertex_tangents_missing 3 'vertex_tangents_missing\.xml:[0-9]+: .*vertex_tangents needs the mesh attribute vertex_tangent ' -- $(r vertex_tangents_missing)
check ply_face_index_out_of_range 3 'index_ascii_ply\.xml:[0-9]+: .*outside the 3 vertices' -- $(r index_ascii_ply)
check ply_vertex_without_xyz 3 'no_xyz_ply\.xml:[0-9]+: .*x, y, z' -- $(r no_xyz_ply)
check ply_degenerate_face 3 'two_corner_face_ply\.xml:[0-9]+: .*at least 3' -- $(r two_corner_face_ply)
check ply_ascii_truncated 3 'short_ascii_ply\.xml:[0-9]+: .*ends before' -- $(r short_ascii_ply)
check ply_bad_header 3 'bad_header_ply\.xml:[0-9]+: .*bad_header\.ply' -- $(r bad_header_ply)
check missing_image 3 'missing_image\.xml:[0-9]+: .*missing\.png' -- $(r missing_image)
check empty_image 3 'empty_image\.xml:[0-9]+: .*empty\.png' -- $(r empty_image)
check corrupt_image 3 'corrupt_image\.xml:[0-9]+: .*corrupt\.png' -- $(r corrupt_image)
check image_is_a_folder 3 'folder_image\.xml:[0-9]+: .*folder\.png' -- $(r folder_image)
check image_header_too_large 3 'huge_image\.xml:[0-9]+: .*65536 per side' -- $(r huge_image)
check image_shorter_than_header 3 'short_image\.xml:[0-9]+: .*ends before' -- $(r short_image)
check nan_radius 3 'nan_radius\.xml:[0-9]+: .*radius' -- $(r nan_radius)
check inf_transform 3 'inf_translate\.xml:[0-9]+: ' -- $(r inf_translate)
check nan_radiance 3 'nan_radiance\.xml:[0-9]+: .*radiance' -- $(r nan_radiance)
check negative_radiance 3 'negative_radiance\.xml:[0-9]+: .*radiance' -- $(r negative_radiance)
check negative_reflectance 3 'negative_reflectance\.xml:[0-9]+: .*reflectance' -- $(r negative_reflectance)
check blend_no_weight 3 'blend_no_weight\.xml:[0-9]+: .*blendbsdf.*weight' -- $(r blend_no_weight)
check blend_one_child 3 'blend_one_child\.xml:[0-9]+: .*two nested BSDFs' -- $(r blend_one_child)
check normalmap_no_texture 3 'normalmap_no_texture\.xml:[0-9]+: .*normalmap' -- $(r normalmap_no_texture)
check normalmap_in_blend 3 'normalmap_in_blend\.xml:[0-9]+: .*normalmap inside a blendbsdf' -- $(r normalmap_in_blend)
check zero_width 3 'zero_width\.xml:[0-9]+: .*width' -- $(r zero_width)
check overflowing_size 3 'overflow_size\.xml:[0-9]+: .*width' -- $(r overflow_size)
check size_beyond_memory 3 'huge_size\.xml:[0-9]+: .*GiB of memory' -- $(r huge_size)
check negative_spp 3 'negative_spp\.xml:[0-9]+: .*sample_count' -- $(r negative_spp)
check empty_scene 0 'twinray: 8x8' -- $(r empty_scene)
check scene_without_emitters 0 'twinray: 8x8' -- $(r no_emitter)
check scene_without_sensor 3 'bare\.xml:[0-9]+: .*no <sensor>' -- render "$d/bare.xml" -o "$d/out/img.exr"
check absurd_spp 2 '--spp' -- $(r ok) --spp 99999999999
check zero_spp 2 '--spp' -- $(r ok) --spp 0
check stratified_pass_too_large 3 'stratified_huge_spp\.xml:[0-9]+: .*sample_count 20000000 exceeds 2\^24' -- $(r stratified_huge_spp)
check stratified_spp_too_large 2 '--spp 20000000: stratified: sample_count 20000000 exceeds 2\^24' -- $(r stratified_ok) --spp 20000000
check no_scene_file 3 'nowhere\.xml' -- render "$d/nowhere.xml" -o "$d/out/img.exr"
check scene_is_a_folder 3 'readonly' -- render "$d/readonly" -o "$d/out/img.exr"
check unwritable_output_folder 5 'proc' -- render "$d/ok.xml" -o /proc/img.exr
check missing_output_folder 5 'does not exist' -- render "$d/ok.xml" -o "$d/nowhere/img.exr"
check unknown_option 2 'unknown option' -- $(r ok) --fast
check define_without_value 2 'NAME=VALUE' -- $(r ok) -D spp
check unknown_backend 2 'backend' -- $(r ok) --backend tpu
check missing_checkpoint 8 'checkpoint' -- $(r ok) --resume "$d/nowhere.checkpoint"
check bad_time_budget 2 '--time' -- $(r ok) --time -3

g() { echo render "$d/$1.gltf" -o "$d/out/img.exr"; }
check gltf_renders 0 'twinray: ' -- $(g gltf_ok) -D width=8 -D height=8 -D spp=2
check gltf_count_beyond_view 3 'gltf_count_beyond_view\.gltf:[0-9]+: accessors\[0\]: 4 elements of 12 bytes' -- $(g gltf_count_beyond_view)
check gltf_view_beyond_buffer 3 'gltf_view_beyond_buffer\.gltf:[0-9]+: bufferViews\[0\]: bytes 0\.\.360 lie outside' -- $(g gltf_view_beyond_buffer)
check gltf_bad_index 3 'gltf_bad_index\.gltf:[0-9]+: .*POSITION: index 7 out of range' -- $(g gltf_bad_index)
check gltf_bad_component 3 'gltf_bad_component\.gltf:[0-9]+: .*unknown component type 5124' -- $(g gltf_bad_component)
check gltf_bad_base64 3 'gltf_bad_base64\.gltf:[0-9]+: buffers\[0\]\.uri: invalid base64' -- $(g gltf_bad_base64)
check gltf_missing_bin 3 'gltf_missing_bin\.gltf:[0-9]+: buffers\[0\]\.uri: file "missing\.bin" not found' -- $(g gltf_missing_bin)
check gltf_required_extension 3 'gltf_required_extension\.gltf:[0-9]+: .*KHR_draco_mesh_compression' -- $(g gltf_required_extension)
check gltf_ior_below_one 3 'gltf_negative_ior\.gltf:[0-9]+: .*ior: must be at least 1' -- $(g gltf_negative_ior)
check gltf_strict_blend 3 'gltf_blend\.gltf:[0-9]+: .*BLEND.*refused: --strict-gltf' -- $(g gltf_blend) --strict-gltf
check gltf_blend_warned 0 'gltf_blend\.gltf:[0-9]+: .*approximate: BLEND as Mitsuba.s mask' -- $(g gltf_blend) -D width=8 -D height=8 -D spp=2
check gltf_no_camera_framed 0 'no node of the scene has a camera: rendered through a camera framing' -- $(g gltf_no_camera) -D width=8 -D height=8 -D spp=2
check gltf_tangent_not_vec4 3 'gltf_tangent_vec3\.gltf:[0-9]+: accessors\[0\]\.type: expected VEC4 for this use' -- $(g gltf_tangent_vec3)
check gltf_camera_out_of_range 3 'gltf_ok\.gltf:[0-9]+: --camera 3: the file has 1 cameras' -- $(g gltf_ok) --camera 3
check gltf_camera_not_a_number 2 '--camera expects auto or a camera index' -- $(g gltf_ok) --camera first
check camera_on_xml 2 '--camera is for glTF scenes' -- $(r ok) --camera 0
check strict_gltf_on_xml 2 '--strict-gltf is for glTF scenes' -- $(r ok) --strict-gltf
check glb_bad_length 3 'gltf_bad_length\.glb:0: GLB header length 64 is not the file.s size 52' -- render "$d/gltf_bad_length.glb" -o "$d/out/img.exr"
check no_emitter_warned 0 'no_emitter\.xml: the scene has no emitter' -- $(r no_emitter)
check envmap_and_constant 2 '--envmap and --constant together' -- $(r no_emitter) --constant 1 --envmap "$d/ok.xml"
check envmap_not_a_file 2 '--envmap: .*is not a file' -- $(r no_emitter) --envmap "$d/nowhere.exr"
check envmap_not_an_image 3 'ok\.xml' -- $(r no_emitter) --envmap "$d/ok.xml"
check envmap_scale_alone 2 '--envmap-scale needs --envmap' -- $(r no_emitter) --envmap-scale 2
check constant_negative 2 '--constant: expected V or R,G,B' -- $(r no_emitter) --constant 1,-1,1
check constant_two_values 2 '--constant: expected V or R,G,B' -- $(r no_emitter) --constant 1,1
check constant_beside_environment 3 'ok\.xml:[0-9]+: .*has an environment already' -- $(r ok) --constant 1
check constant_lights_no_emitter 0 'twinray: 8x8' -- $(r no_emitter) --constant 0.5,1,2

echo "$cases cases, $failures failed"
exit $((failures > 0))
