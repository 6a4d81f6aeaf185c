#!/usr/bin/env bash
# Render budgets (issue 12). usage: budgets.sh TWINRAY SCENE
#  - --target-error E stops on the error, with an estimate <= E, and the estimate is calibrated:
#    two renders of other seeds differ by relMSE ~ 2 E^2 (each is E from the truth), so
#    sqrt(relMSE / 2) must lie within 20% of E;
#  - --time stops on the time budget, below the spp cap, with outputs stating the true spp.
set -u
export LC_ALL=C
twinray=$1 scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
target=0.05
for seed in 1 2; do
  "$twinray" render "$scene" -D width=32 -D height=32 --spp 1000000 --seed "$seed" \
    --target-error "$target" -o "$dir/e$seed.exr" >"$dir/e$seed.log" 2>&1 ||
    { cat "$dir/e$seed.log"; fail "target-error render"; }
  cat "$dir/e$seed.log"
  grep -q "stopped: error" "$dir/e$seed.log" || fail "seed $seed did not stop on the error"
  reached=$(sed -n 's/.*estimated relative error \([0-9.e-]*\).*/\1/p' "$dir/e$seed.log")
  awk -v r="$reached" -v t="$target" 'BEGIN { exit !(r <= t) }' ||
    fail "estimate $reached above the target $target"
done
relmse=$("$twinray" compare "$dir/e1.exr" "$dir/e2.exr" | sed -n 's/.*relMSE \([0-9.e-]*\).*/\1/p')
echo "two seeds: relMSE $relmse"
awk -v m="$relmse" -v t="$target" 'BEGIN { e = sqrt(m / 2); print "per-render error", e;
  exit !(e >= 0.8 * t && e <= 1.2 * t) }' || fail "error estimate not within 20% of the measured"

"$twinray" render "$scene" -D width=32 -D height=32 --spp 1000000 --time 1 \
  -o "$dir/t.exr" >"$dir/t.log" 2>&1 || { cat "$dir/t.log"; fail "time-budget render"; }
cat "$dir/t.log"
grep -q "stopped: time" "$dir/t.log" || fail "did not stop on the time budget"
spp=$(oiiotool --info -v "$dir/t.exr" | sed -n 's/.*twinray:spp: "\([0-9]*\)".*/\1/p')
[ -n "$spp" ] && [ "$spp" -gt 0 ] && [ "$spp" -lt 1000000 ] || fail "image states spp '$spp'"
grep -q "twinray: 32x32, $spp spp" "$dir/t.log" || fail "summary and image disagree on spp"
echo "budgets.sh: pass"
