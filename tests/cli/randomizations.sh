#!/usr/bin/env bash
# render --randomizations K (issue 11): a correlated sampler's render as K independent passes.
#  - the pass is ceil(spp / K) rounded as the sampler rounds sample_count, spp K times that; the
#    summary and the EXRs' twinray:variance_estimate say so;
#  - without it a correlated sampler's render warns on stderr that its variance is no error
#    estimate, naming the option; `independent` accepts the option and renders the same image;
#  - --target-error trusts the pass estimate from 16 passes on;
#  - a checkpoint of K passes resumes to a render of more passes of the same size, bit for bit;
#  - K = 0 is a usage error.
set -u
export LC_ALL=C
twinray=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
scene() {  # sampler type
  {
    echo '<scene version="3.0.0"><emitter type="constant"/>'
    echo '  <shape type="sphere"><transform name="to_world"><translate z="4"/></transform>'
    echo '    <bsdf type="diffuse"/></shape>'
    echo "  <sensor type=\"perspective\"><sampler type=\"$1\">"
    echo '    <integer name="sample_count" value="16"/></sampler>'
    echo '    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>'
    echo '  </sensor></scene>'
  } >"$dir/$1.xml"
}
meta() { oiiotool --info -v "$1" | sed -n "s/.*$2: \"\(.*\)\"/\1/p"; }
same() {
  oiiotool "$1" "$2" --fail 0 --warn 0 --diff >"$dir/diff.txt" 2>&1 ||
    { cat "$dir/diff.txt"; fail "$1 and $2 differ"; }
}
scene zsobol
scene independent

"$twinray" render "$dir/zsobol.xml" --spp 100 --randomizations 4 -o "$dir/k4.exr" \
  >"$dir/k4.log" 2>"$dir/k4.err" || { cat "$dir/k4.log" "$dir/k4.err"; fail "K = 4"; }
grep -q '^twinray: 8x8, 128 spp' "$dir/k4.log" || { cat "$dir/k4.log"; fail "expected 128 spp"; }
grep -q '^twinray: --randomizations 4: 4 independent passes of 32 samples (zsobol)$' \
  "$dir/k4.log" || { cat "$dir/k4.log"; fail "no randomizations line"; }
[ ! -s "$dir/k4.err" ] || { cat "$dir/k4.err"; fail "K = 4 printed on stderr"; }
for f in k4.exr k4_var.exr; do
  [ "$(meta "$dir/$f" twinray:variance_estimate)" = "randomizations: 4 passes of 32 samples" ] ||
    fail "$f: twinray:variance_estimate is '$(meta "$dir/$f" twinray:variance_estimate)'"
done

"$twinray" render "$dir/zsobol.xml" -o "$dir/one.exr" >"$dir/one.log" 2>"$dir/one.err" ||
  { cat "$dir/one.log" "$dir/one.err"; fail "one pass"; }
[ "$(wc -l <"$dir/one.err")" = 1 ] && grep -q 'warning: .*not an error estimate.*--randomizations' \
  "$dir/one.err" || { cat "$dir/one.err"; fail "no warning for one pass"; }
[ "$(meta "$dir/one_var.exr" twinray:variance_estimate)" = per-sample ] ||
  fail "one pass: twinray:variance_estimate is not per-sample"

"$twinray" render "$dir/independent.xml" -o "$dir/i.exr" >/dev/null 2>"$dir/i.err" || fail "independent"
"$twinray" render "$dir/independent.xml" --randomizations 4 -o "$dir/i4.exr" >"$dir/i4.log" \
  2>>"$dir/i.err" || fail "independent, K = 4"
[ ! -s "$dir/i.err" ] || { cat "$dir/i.err"; fail "independent printed on stderr"; }
grep -q '^twinray: 8x8, 16 spp' "$dir/i4.log" || { cat "$dir/i4.log"; fail "independent: spp changed"; }
same "$dir/i.exr" "$dir/i4.exr"
same "$dir/i_var.exr" "$dir/i4_var.exr"

# --target-error: not estimated below 16 passes, trusted from there on.
"$twinray" render "$dir/zsobol.xml" --spp 64 --randomizations 2 --target-error 1e9 \
  -o "$dir/e2.exr" >"$dir/e2.log" 2>&1 || { cat "$dir/e2.log"; fail "target-error, K = 2"; }
grep -q 'stopped: spp; relative error not estimated below 16 passes (2 done)' "$dir/e2.log" ||
  { cat "$dir/e2.log"; fail "K = 2 estimated the error"; }
"$twinray" render "$dir/zsobol.xml" --spp 1000000 --randomizations 31250 --target-error 1e9 \
  -o "$dir/e.exr" >"$dir/e.log" 2>&1 || { cat "$dir/e.log"; fail "target-error, K = 31250"; }
grep -q 'stopped: error' "$dir/e.log" || { cat "$dir/e.log"; fail "did not stop on the error"; }
spp=$(meta "$dir/e.exr" twinray:spp)
[ "$spp" -ge 512 ] && [ "$spp" -lt 1000000 ] || fail "stopped on the error at $spp spp"

# A checkpoint of 2 passes of 32, resumed to 4 passes of 32, is the render of 4 passes.
"$twinray" render "$dir/zsobol.xml" --spp 64 --randomizations 2 --checkpoint 1000 \
  -o "$dir/c.exr" >"$dir/c.log" 2>&1 || { cat "$dir/c.log"; fail "checkpointed render"; }
"$twinray" render "$dir/zsobol.xml" --spp 128 --randomizations 4 --resume "$dir/c.checkpoint" \
  -o "$dir/c.exr" >"$dir/c2.log" 2>&1 || { cat "$dir/c2.log"; fail "resume"; }
same "$dir/k4.exr" "$dir/c.exr"
same "$dir/k4_var.exr" "$dir/c_var.exr"

"$twinray" render "$dir/zsobol.xml" --randomizations 0 >/dev/null 2>&1
[ $? = 2 ] || fail "--randomizations 0: expected exit 2"
echo "randomizations.sh: pass"
