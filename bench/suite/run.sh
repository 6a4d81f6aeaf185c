#!/usr/bin/env bash
# Issue 15's end-to-end suite: fixed scenes rendered by `twinray render` on the CPU backend,
# each once, with their time, throughput and peak resident set size, as a Markdown table.
#
# usage: bench/suite/run.sh [--full] [--write] OUT_DIR
#   OUT_DIR   the generated scenes, renders and logs go here (never into the repository)
#   --full    also the 1e7-triangle mesh and the 1e5-emitter scene (minutes, GiBs)
#   --write   replace the table between the bench/suite markers of BENCHMARKS.md
# env: TWINRAY (build/app/twinray), THREADS (2), SCENES (all; names as in the table, e.g.
#      "cbox_mitsuba mesh_1000000")
#
# Settings (fixed; each scene's own -D defaults are overridden here):
#   cornell_box        examples/scenes/cornell-box/cornell_box.xml at its defaults: 512x512,
#                      64 spp, max_depth 8
#   cbox_mitsuba       ../shared/perf/mitsuba-cbox/cbox-rgb.xml, 256x256, 64 spp, max_depth 6
#   cornell_principled bench/scenes/cornell_principled.xml (the Cornell box with `principled`
#                      everywhere) at 512x512, 64 spp, max_depth 8
#   mesh_N             gen.py mesh (N = 1e6; --full adds 1e7), 256x256, 32 spp, max_depth 6
#   emitters_N         gen.py emitters (N = 1 ... 1e4; --full adds 1e5), 256x256, 64 spp,
#                      max_depth 4
#   envmap             gen.py envmap (512x256 sky), 384x216, 64 spp, max_depth 8
# Columns: "render s" is twinray's own figure (the Embree BVH build and the sampling; not
# scene loading or image writing); "wall s" is the whole process (/usr/bin/time %e), so
# wall - render is the scene load (parsing, mesh files, emitter and envmap tables) plus writing
# the EXRs and PNG: twinray prints no start-up time of its own. Peak RSS is /usr/bin/time's %M;
# CPU its %P, the process's CPU time over wall time (200% = both cores of the 2-core VM busy
# with it throughout: less says how much other processes took).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
twinray=${TWINRAY:-$root/build/app/twinray}
threads=${THREADS:-2}
full=0 write=0 out=
for a in "$@"; do
  case $a in
    --full) full=1 ;;
    --write) write=1 ;;
    -*) echo "run.sh: unknown option '$a'" >&2 && exit 2 ;;
    *) [ -z "$out" ] || { echo "run.sh: one OUT_DIR only" >&2 && exit 2; }; out=$a ;;
  esac
done
[ -n "$out" ] || { echo "usage: bench/suite/run.sh [--full] [--write] OUT_DIR" >&2 && exit 2; }
case $(realpath -m "$out")/ in
  "$root"/*) echo "run.sh: OUT_DIR must be outside the repository ($root)" >&2 && exit 2 ;;
esac
[ -x /usr/bin/time ] || { echo "run.sh: /usr/bin/time (GNU time) is needed" >&2 && exit 2; }
[ -x "$twinray" ] || { echo "run.sh: $twinray not built" >&2 && exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
uptime_before=$(uptime | sed 's/^ *//')

mesh_sizes=(1000000) emitter_counts=(1 10 100 1000 10000)
[ $full = 1 ] && mesh_sizes+=(10000000) && emitter_counts+=(100000)

# name scene-file render-arguments..., in table order
declare -a names=() files=() args=()
add() { names+=("$1") files+=("$2") args+=("$3"); }
add cornell_box "$root/examples/scenes/cornell-box/cornell_box.xml" ""
add cbox_mitsuba "$root/../shared/perf/mitsuba-cbox/cbox-rgb.xml" "-D res=256 -D spp=64 -D max_depth=6"
add cornell_principled "$root/bench/scenes/cornell_principled.xml" "-D width=512 -D height=512 -D spp=64 -D max_depth=8"
for n in "${mesh_sizes[@]}"; do add "mesh_$n" "gen:mesh --triangles $n" "-D spp=32"; done
for n in "${emitter_counts[@]}"; do add "emitters_$n" "gen:emitters --count $n" "-D spp=64"; done
add envmap "gen:envmap" "-D spp=64"

selected() { [ -z "${SCENES:-}" ] || [[ " $SCENES " == *" $1 "* ]]; }

rows=()
for i in "${!names[@]}"; do
  name=${names[$i]} file=${files[$i]}
  selected "$name" || continue
  if [[ $file == gen:* ]]; then
    read -r -a gen <<<"${file#gen:}"
    gen_start=$(date +%s.%N)
    file=$(python3 "$here/gen.py" "${gen[0]}" "$out" "${gen[@]:1}")
    gen_s=$(awk -v a="$gen_start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
    # gen.py names the mesh after its actual triangle count, which can differ from the one asked.
    name=$(basename "$file" .xml)
    printf '%s: generated in %.1f s\n' "$name" "$gen_s" >&2
  fi
  [ -f "$file" ] || { echo "run.sh: $file: scene missing" >&2 && exit 3; }
  read -r tris analytic emitters <<<"$(python3 "$here/gen.py" count "$file")"
  [ "$analytic" = 0 ] || tris="$tris + $analytic analytic"
  log=$out/$name.log
  # shellcheck disable=SC2086  # the render arguments are words
  if ! /usr/bin/time -f '%e %M %P' -o "$out/$name.time" "$twinray" render "$file" ${args[$i]} \
    --threads "$threads" -o "$out/$name.exr" >"$log" 2>&1; then
    echo "run.sh: $name: twinray render failed; $log:" >&2 && cat "$log" >&2 && exit 1
  fi
  # twinray: 256x256, 64 spp, 1.234 s, 3.400 Msamples/s, 9.100 Mrays/s, 0 NaN/Inf ...
  summary=$(grep -E '^twinray: [0-9]+x[0-9]+, [0-9]+ spp, ' "$log" | head -1)
  [ -n "$summary" ] || { echo "run.sh: $name: no summary line in $log" >&2 && exit 1; }
  read -r res spp render msps mrps <<<"$(echo "$summary" |
    sed -E 's/^twinray: ([0-9]+x[0-9]+), ([0-9]+) spp, ([0-9.]+) s, ([0-9.]+) Msamples\/s, ([0-9.]+) Mrays\/s.*/\1 \2 \3 \4 \5/')"
  read -r wall rss_kib cpu <"$out/$name.time"
  row=$(awk -v n="$name" -v t="$tris" -v e="$emitters" -v r="$res" -v s="$spp" -v ren="$render" \
    -v w="$wall" -v ms="$msps" -v mr="$mrps" -v k="$rss_kib" -v c="$cpu" 'BEGIN {
      sub("x", "×", r)
      printf "| %s | %s | %s | %s | %s | %.2f | %.2f | %.2f | %s | %.3f | %.3f | %.1f |", n, t, e,
             r, s, ren, w, w - ren, c, ms, mr, k / 1024 }')
  echo "$row" >&2
  rows+=("$row")
done

table=$(
  echo "| scene | triangles | emitters | resolution | spp | render s | wall s | wall − render s | CPU | Msamples/s | Mrays/s | peak RSS MiB |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
)
echo "$table"

if [ $write = 1 ]; then
  bm=$root/BENCHMARKS.md
  if ! grep -q '^<!-- bench/suite begin -->$' "$bm" || ! grep -q '^<!-- bench/suite end -->$' "$bm"; then
    echo "run.sh: $bm has no bench/suite markers" >&2 && exit 3
  fi
  flags=
  [ $full = 1 ] && flags="--full "
  block=$(
    echo "<!-- bench/suite begin -->"
    echo "Measured $(date -u '+%Y-%m-%d %H:%M UTC') by \`bench/suite/run.sh ${flags}--write OUT_DIR\`"
    echo "(the checkout at $(git -C "$root" describe --always --dirty), $threads threads, $(nproc) cores;"
    echo "\`uptime\` before the run: \`$uptime_before\`, after: \`$(uptime | sed 's/^ *//')\`)."
    echo
    echo "$table"
    echo "<!-- bench/suite end -->"
  )
  tmp=$(mktemp)
  block=$block awk '
    /^<!-- bench\/suite begin -->$/ { print ENVIRON["block"]; skip = 1; next }
    /^<!-- bench\/suite end -->$/ { skip = 0; next }
    !skip' "$bm" >"$tmp"
  cat "$tmp" >"$bm"
  rm "$tmp"
  echo "run.sh: wrote the table into $bm" >&2
fi
