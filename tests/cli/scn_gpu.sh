#!/usr/bin/env bash
# The two seed .scn scenes and tests/cli/scenes/scn/features.scn (principled, bitmap maps, a
# tent filter) on the GPU backend (issue 13's acceptance): 16 spp at 32x18, in lockstep with the
# CPU at the same seed (twinray compare --lockstep: at least 99% of the pixels
# within 1e-4 relative, no systematic or clustered 4x4 window).
set -u
twinray=$1
seed_dir=$2
scene_dir=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for scene in "$seed_dir/cornellbox_original.scn" "$seed_dir/cornellbox_sphere.scn" \
  "$scene_dir/features.scn"; do
  name=$(basename "$scene" .scn)
  for backend in cpu gpu; do
    "$twinray" render "$scene" -D width=32 -D height=18 --spp 16 --seed 5 \
      --backend $backend -o "$work/${name}_$backend.exr" >/dev/null 2>"$work/err" ||
      { echo "FAIL $name: $backend render: $(cat "$work/err")"; failures=$((failures + 1)); continue 2; }
  done
  if "$twinray" compare "$work/${name}_gpu.exr" "$work/${name}_cpu.exr" --lockstep >"$work/cmp" 2>&1; then
    echo "ok $name: $(grep 'lockstep ' "$work/cmp")"
  else
    echo "FAIL $name: $(cat "$work/cmp")"
    failures=$((failures + 1))
  fi
done
exit $((failures > 0))
