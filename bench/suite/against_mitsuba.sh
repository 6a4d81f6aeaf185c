#!/usr/bin/env bash
# Issue 15's side-by-side: Mitsuba 3 `scalar_rgb` and twinray's CPU backend render Mitsuba's
# Cornell box (../shared/perf/mitsuba-cbox/cbox-rgb.xml, 256x256, max_depth 6 as the scene
# sets it) with the same thread count, alternating, and print a Markdown table of the medians
# (min-max) of whole-process seconds, render-phase seconds and peak RSS.
#
# usage: bench/suite/against_mitsuba.sh MITSUBA_BUILD_DIR OUT_DIR
#   MITSUBA_BUILD_DIR  a Mitsuba build with the scalar_rgb variant (its `mitsuba`, libraries and
#                      plugins/; validation/mitsuba/README.md says how to build one)
#   OUT_DIR            copies of both programs, the renders and the raw log (never the repository)
# env: TWINRAY (build/app/twinray), THREADS (2), SPP (64), ROUNDS (5), ROBUST (unset: the scene
#      as it is; true or false: a copy of it in OUT_DIR that sets <scene>'s
#      embree_use_robust_intersections, Mitsuba's default false, twinray's true; scenes/README.md)
#
# Each program runs as two fresh copies of its files (Mitsuba's libraries and plugins found
# through LD_LIBRARY_PATH): on the 2-core VM the same bytes in another file can run 15-20%
# faster or slower (BENCHMARKS.md, "CPU kernels"). After one warm-up run of each, ROUNDS
# rounds of Mitsuba 1, twinray 1, Mitsuba 2, twinray 2. Render phase: Mitsuba's "Rendering
# finished. (took ...)" line and twinray's summary line.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
[ $# -eq 2 ] || { echo "usage: $0 MITSUBA_BUILD_DIR OUT_DIR" >&2; exit 2; }
mts=$(cd "$1" && pwd)
out=$2
twinray=${TWINRAY:-$root/build/app/twinray}
threads=${THREADS:-2}
spp=${SPP:-64}
rounds=${ROUNDS:-5}
scene_dir=$root/../shared/perf/mitsuba-cbox
[ -x "$mts/mitsuba" ] || { echo "$0: no mitsuba executable in $mts" >&2; exit 2; }
[ -f "$scene_dir/cbox-rgb.xml" ] || { echo "$0: $scene_dir/cbox-rgb.xml not found" >&2; exit 2; }
mkdir -p "$out"
if [ -n "${ROBUST:-}" ]; then
  [ "$ROBUST" = true ] || [ "$ROBUST" = false ] || { echo "$0: ROBUST must be true or false" >&2; exit 2; }
  rm -rf "$out/scene" && cp -r "$scene_dir" "$out/scene" && chmod -R u+w "$out/scene"
  sed -i "0,/<scene version=\"3.0.0\">/s//&\n    <boolean name=\"embree_use_robust_intersections\" value=\"$ROBUST\"\/>/" \
    "$out/scene/cbox-rgb.xml"
  grep -q embree_use_robust_intersections "$out/scene/cbox-rgb.xml"
  scene_dir=$(cd "$out/scene" && pwd)
fi
for c in 1 2; do
  rm -rf "$out/mitsuba$c" && mkdir -p "$out/mitsuba$c"
  cp -a "$mts/mitsuba" "$mts"/*.so* "$mts/plugins" "$out/mitsuba$c/"
  cp "$twinray" "$out/twinray$c"
done
log=$out/runs.log
: >"$log"
run() {  # M|T copy
  local times=$out/time.txt
  cd "$scene_dir"
  if [ "$1" = M ]; then
    LD_LIBRARY_PATH=$out/mitsuba$2 /usr/bin/time -o "$times" -f "%e %M" "$out/mitsuba$2/mitsuba" \
      -m scalar_rgb -t "$threads" -D res=256 -D spp="$spp" -o "$out/mitsuba.exr" cbox-rgb.xml \
      >"$out/last.txt" 2>&1
    render=$(sed -nE 's/.*Rendering finished\. \(took ([0-9.]+)([a-z]+)\).*/\1 \2/p' "$out/last.txt" |
      awk '{print $1 * ($2 == "m" ? 60 : $2 == "ms" ? 0.001 : 1)}')
  else
    /usr/bin/time -o "$times" -f "%e %M" "$out/twinray$2" render cbox-rgb.xml --threads "$threads" \
      --spp "$spp" -D res=256 -o "$out/twinray.exr" >"$out/last.txt" 2>&1
    render=$(sed -nE 's/^twinray: [0-9]+x[0-9]+, [0-9]+ spp, ([0-9.]+) s,.*/\1/p' "$out/last.txt")
  fi
  cd - >/dev/null
  echo "$1 $2 $render $(cat "$times")" >>"$log"
}
run M 1
run T 1
: >"$log"
for _ in $(seq "$rounds"); do
  for c in 1 2; do run M "$c"; run T "$c"; done
done
python3 - "$log" "$threads" "$spp" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip()]
def col(kind, i, scale=1.0):
    return [float(r[i]) * scale for r in rows if r[0] == kind]
def cell(v, fmt):
    return (fmt + " (" + fmt + "–" + fmt + ")") % (statistics.median(v), min(v), max(v))
print(f"Mitsuba's box, 256x256, {sys.argv[3]} spp, {sys.argv[2]} threads, {len(col('M', 2))} runs each:\n")
print("| measure | Mitsuba `scalar_rgb` | twinray CPU | Mitsuba ÷ twinray |")
print("|---|---|---|---|")
for name, i, scale, fmt in (("whole process, s", 3, 1.0, "%.2f"), ("render phase, s", 2, 1.0, "%.3f"),
                            ("peak RSS, MiB", 4, 1 / 1024, "%.1f")):
    m, t = col("M", i, scale), col("T", i, scale)
    print(f"| {name} | {cell(m, fmt)} | {cell(t, fmt)} | {statistics.median(m) / statistics.median(t):.2f} |")
PY
