#!/usr/bin/env bash
# What each plugin of the Mitsuba plugins issue costs the GPU backend, in a scene that uses it
# (against a control scene that differs only by the plugin) and in one that does not (the
# Cornell box, specialized and all-features). Numbers and commands in BENCHMARKS.md.
#   gpu_costs.sh dump BUILD OUT   scene dumps of every scene into OUT (needs the scene loader)
#   gpu_costs.sh run BUILD OUT    gpu_bench over every dump of OUT, three runs each (the GPU
#                                 machine needs only BUILD/tests/gpu/gpu_bench_dump_only)
set -euo pipefail
mode=$1 build=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
size=(-D width=1280 -D height=720 -D max_depth=5)
spp=${SPP:-256}

if [ "$mode" = dump ]; then
  mkdir -p "$out"
  # The aov integrator replaces the Cornell box's own, so it gets a copy of the box that finds
  # its meshes through <path>.
  sed -e 's|<scene version="3.0.0">|&<path value="'"$root"'/examples/scenes/cornell-box"/>|' \
      -e 's|<integrator type="path">|<integrator type="aov"><string name="aovs" value="a:albedo,d:depth,p:position,t:uv,g:geo_normal,n:sh_normal,i:prim_index,s:shape_index"/><integrator type="path">|' \
      -e 's|</integrator>|</integrator></integrator>|' \
      "$root/examples/scenes/cornell-box/cornell_box.xml" >"$out/cornell_aov.xml"
  scenes=("$root/examples/scenes/cornell-box/cornell_box.xml" "$out/cornell_aov.xml" "$here"/cornell_*.xml)
  for s in "${scenes[@]}"; do
    "$build/tests/gpu/gpu_bench" "$s" "${size[@]}" --save "$out/$(basename "$s" .xml).bin"
  done
  ls "$out"/*.bin
elif [ "$mode" = run ]; then
  bench() { for k in 1 2 3; do "$build/tests/gpu/gpu_bench_dump_only" "$@" --spp "$spp"; done; }
  for d in "$out"/*.bin; do
    echo "== $(basename "$d" .bin) specialized"
    bench "$d"
  done
  echo "== cornell_box all-features"
  bench "$out/cornell_box.bin" --all-features
else
  echo "usage: gpu_costs.sh dump|run BUILD OUT" >&2
  exit 2
fi
