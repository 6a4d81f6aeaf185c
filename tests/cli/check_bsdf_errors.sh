#!/bin/bash
# `twinray check-bsdf` on bad input (issue 16): a shader (GLSL or HLSL) that does not compile
# exits 3 with glslang's error as FILE:LINE, a malformed parameter declaration exits 3 with
# FILE:LINE, usage errors exit 2 (bad --against and --convention included), an unknown device 4,
# an unwritable JSON report or plot 5, and a sample() that never succeeds fails (exit 1).
#   check_bsdf_errors.sh TWINRAY EXAMPLES_DIR
set -u
twinray=$1
examples=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
expect() {  # expect STATUS REGEX ARGS...: exit status and a line of stderr+stdout
  local status=$1 regex=$2
  shift 2
  "$twinray" check-bsdf "$@" >"$dir/out" 2>&1
  local got=$?
  if [ "$got" != "$status" ] || ! grep -Eq "$regex" "$dir/out"; then
    echo "FAIL: check-bsdf $* exited $got (expected $status), output:"
    cat "$dir/out"
    fail=1
  else
    echo "ok: check-bsdf $* -> $got: $(grep -E "$regex" "$dir/out" | head -1)"
  fi
}
# An undeclared identifier on line 10 of a copy of the Lambertian.
sed '10s/return vec3(0.0);/return vec3(undeclared_value);/' "$examples/lambert.glsl" >"$dir/bad.glsl"
sed -n 10p "$dir/bad.glsl" | grep -q undeclared_value || { echo "FAIL: line 10 not edited"; exit 1; }
expect 3 "^$dir/bad.glsl:10: .*undeclared_value" "$dir/bad.glsl"
# A syntax error on line 6.
sed '6s/= 3.14159265358979;/= 3.14159 265358979;/' "$examples/lambert.glsl" >"$dir/syntax6.glsl"
expect 3 "^$dir/syntax6.glsl:6: .*syntax error" "$dir/syntax6.glsl"
# An unterminated declaration on the last line (glslang finds the error in the wrapper).
{ cat "$examples/lambert.glsl"; echo "vec3 oops("; } >"$dir/syntax.glsl"
expect 3 "^$dir/syntax.glsl:[0-9]+: " "$dir/syntax.glsl"
# A file without user_pdf.
grep -v 'float user_pdf' "$examples/lambert.glsl" | sed '/^\/\/ Cosine-weighted/,/^}/d' >"$dir/nopdf.glsl"
expect 3 "user_pdf" "$dir/nopdf.glsl"
# A malformed parameter declaration on line 2.
printf '// x\n#pragma twinray_param albedo\n' >"$dir/pragma.glsl"
expect 3 "^$dir/pragma.glsl:2: " "$dir/pragma.glsl"
expect 3 "cannot read" "$dir/missing.glsl"
# HLSL: an undeclared identifier on line 11 of a copy of the HLSL Lambertian.
sed '11s/return float3(0.0, 0.0, 0.0);/return undeclared_value;/' "$examples/lambert.hlsl" >"$dir/bad.hlsl"
sed -n 11p "$dir/bad.hlsl" | grep -q undeclared_value || { echo "FAIL: line 11 not edited"; exit 1; }
expect 3 "^$dir/bad.hlsl:11: .*undeclared_value" "$dir/bad.hlsl"
# A sample() whose every draw fails passes validation/bsdf's checks; the "draws" check fails it.
sed 's/^  pdf = wo.z \/ USER_PI;/  pdf = 0.0;/' "$examples/lambert.glsl" >"$dir/never.glsl"
grep -q '^  pdf = 0.0;$' "$dir/never.glsl" || { echo "FAIL: never.glsl not edited"; exit 1; }
expect 1 "^FAILED draws .*theta_i=89.9 .*0 of 1024" "$dir/never.glsl" --samples 20000
expect 2 "no shader file" --samples 20000
expect 2 "declares no such parameter" "$examples/lambert.glsl" --params roughness=0.5
expect 2 "not a finite number" "$examples/lambert.glsl" --params albedo=x
expect 2 "unknown option" "$examples/lambert.glsl" --frobnicate
expect 4 "no-such-device" "$examples/lambert.glsl" --device no-such-device
expect 5 "cannot write" "$examples/lambert.glsl" --samples 1000 --json "$dir/no/such/folder.json"
# --against and --convention (a plugin or parameter twinray's loader refuses is a usage error).
ggx=$examples/ggx_conductor.glsl
expect 2 "^twinray check-bsdf: --against nosuch: .*not supported" "$ggx" --against nosuch alpha=0.3
expect 2 "^twinray check-bsdf: --against roughconductor alpah=0.3: unused parameter 'alpah'" \
  "$ggx" --against roughconductor distribution=ggx alpah=0.3
expect 2 "check-bsdf: --against: 'alpha=' is not NAME=VALUE" "$ggx" --against roughconductor alpha=
expect 2 "check-bsdf: --against compares one parameter set; --params gives 2" "$ggx" --against \
  roughconductor --params alpha=0.1/0.2
expect 2 "check-bsdf: --plot needs --against" "$ggx" --plot "$dir/plot.svg"
expect 2 "check-bsdf: --convention: 'normal=x' is none of" "$ggx" --convention normal=x
expect 5 "cannot write the plot" "$ggx" --samples 1000 --against roughconductor distribution=ggx \
  --plot "$dir/no/such/folder.svg"
# A written plot is a whole SVG document with one cell per (theta_i, theta_o).
expect 0 "^PASS" "$ggx" --samples 1000 --against roughconductor distribution=ggx alpha=0.3 eta=0.2 \
  k=3 --plot "$dir/diff.svg"
python3 -c 'import sys, xml.dom.minidom as m; d = m.parse(sys.argv[1]); sys.exit(0 if len([r for r in d.getElementsByTagName("rect") if r.getElementsByTagName("title")]) == 19 * 19 else 1)' "$dir/diff.svg" ||
  { echo "FAIL: $dir/diff.svg is not the heat map"; fail=1; }
exit $fail
