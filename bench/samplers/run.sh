#!/usr/bin/env bash
# The samplers issue's benchmark: relMSE against render time for every sampler on (a)
# bench/samplers/direct_lit.xml (128 x 128, direct light and a soft shadow), (b) twinray's
# default Cornell box (mirror and glass spheres) at max_depth 6 (64 x 64) and (c) Mitsuba's
# Cornell box (../shared/perf/mitsuba-cbox/cbox-rgb.xml, its own max_depth 6; 64 x 64), against
# an `independent` reference of REF_SPP samples per pixel (seed 1000: independent of every
# measured render). The reference's own error adds to every relMSE measured (about
# relMSE(independent, 1024 spp) / 64 at the defaults), so the gains of the better samplers are
# understated, never overstated. Each rung of `twinray converge`, 64 to 1024 spp, is the mean of
# REPEATS renders with distinct seeds, with its standard error.
#
# usage: bench/samplers/run.sh [OUT]      (default OUT: bench-samplers)
# env:   TWINRAY (build/app/twinray), REF_SPP (65536), REPEATS (8), THREADS (all cores),
#        MAX_SPP (1024; smaller for a quick try), SCENES ("direct_lit cornell_box mitsuba_cbox"),
#        SAMPLERS (all: "independent stratified multijitter orthogonal ldsampler zsobol sobol")
# Writes OUT/<scene>/{reference.exr, convergence.csv, convergence.svg, time_to_error.csv} and
# prints relMSE at 64 and 1024 spp per sampler (mean +- standard error, seconds per render);
# then, in OUT/<scene>/estimate/, whether each sampler's error estimate is honest: at MAX_SPP
# in 16 randomizations (render --randomizations 16) and in one pass, the relMSE observed among
# the REPEATS renders against the one their variance outputs claim.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-bench-samplers}
twinray=${TWINRAY:-$root/build/app/twinray}
ref_spp=${REF_SPP:-65536} repeats=${REPEATS:-8} max_spp=${MAX_SPP:-1024}
threads=()
[ -n "${THREADS:-}" ] && threads=(--threads "$THREADS")
read -r -a samplers <<<"${SAMPLERS:-independent stratified multijitter orthogonal ldsampler zsobol sobol}"

bench() {  # bench NAME SCENE DEFINES...
  local name=$1 scene=$2
  shift 2
  local dir=$out/$name variants=()
  mkdir -p "$dir"
  for s in "${samplers[@]}"; do variants+=(--variant "sampler=$s,label=$s"); done
  "$twinray" render "$scene" "$@" --spp "$ref_spp" --seed 1000 "${threads[@]}" \
    -o "$dir/reference.exr" >/dev/null
  "$twinray" converge "$scene" "$@" --reference "$dir/reference.exr" --budget 100000 \
    --start-spp 64 --max-spp "$max_spp" --repeats "$repeats" "${threads[@]}" "${variants[@]}" \
    --out "$dir" >"$dir/converge.log"
  echo "$name: relMSE (mean +- standard error over $repeats seeds), seconds per render"
  awk -F, -v max="$max_spp" 'NR > 1 { split($1, n, " "); if ($3 == $3 + 0 && ($3 <= 64 || $3 >= max))
             printf "  %-12s %5d spp  %.4g +- %.2g  %.3f s\n", n[1], $3, $5, $6, $2 }' \
    "$dir/convergence.csv"
  # The error estimate: each sampler at MAX_SPP in 16 independent randomizations, and (for the
  # correlated ones) in one pass, whose variance output is only the per-sample variance.
  variants=()
  for s in "${samplers[@]}"; do
    variants+=(--variant "sampler=$s,randomizations=16,label=$s/16")
    [ "$s" = independent ] || variants+=(--variant "sampler=$s,label=$s/1")
  done
  "$twinray" converge "$scene" "$@" --reference "$dir/reference.exr" --budget 100000 \
    --start-spp "$max_spp" --max-spp "$max_spp" --repeats "$repeats" "${threads[@]}" \
    "${variants[@]}" --out "$dir/estimate" >"$dir/estimate.log"
  echo "$name: relMSE among $repeats seeds, the renders' own estimate of it, their ratio"
  awk -F, 'NR > 1 { split($1, n, " ");
             printf "  %-16s %5d spp  %.4g  %.4g  %.3f\n", n[1], $3, $9, $8, $8 / $9 }' \
    "$dir/estimate/convergence.csv"
}

for name in ${SCENES:-direct_lit cornell_box mitsuba_cbox}; do
  case $name in
    direct_lit) bench direct_lit "$root/bench/samplers/direct_lit.xml" ;;
    cornell_box)
      bench cornell_box "$root/examples/scenes/cornell-box/cornell_box.xml" -D max_depth=6 -D width=64 \
        -D height=64
      ;;
    mitsuba_cbox)
      bench mitsuba_cbox "$root/../shared/perf/mitsuba-cbox/cbox-rgb.xml" -D res=64
      ;;
    *) echo "run.sh: unknown scene '$name'" >&2 && exit 2 ;;
  esac
done
