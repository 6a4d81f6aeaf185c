#!/usr/bin/env bash
# Command-line misuse exits with status 2 and a message; --help exits 0; a GPU device that is not
# there is status 4 (whether the build has the GPU backend, Vulkan or no device at all).
set -u
twinray=$1
"$twinray" render >/dev/null 2>&1; [ $? -eq 2 ] || { echo "render without a scene: expected 2"; exit 1; }
"$twinray" render x.xml --spp zero >/dev/null 2>&1; [ $? -eq 2 ] || { echo "--spp zero: expected 2"; exit 1; }
"$twinray" frobnicate >/dev/null 2>&1; [ $? -eq 2 ] || { echo "unknown verb: expected 2"; exit 1; }
"$twinray" render --help >/dev/null || { echo "render --help: expected 0"; exit 1; }
box=$(dirname "$0")/../../examples/scenes/cornell-box/cornell_box.xml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$twinray" render "$box" -D width=4 -D height=4 --spp 1 -o "$work/x.exr" --backend gpu --device 99 \
  >/dev/null 2>&1
[ $? -eq 4 ] || { echo "--device 99: expected 4"; exit 1; }
echo ok
