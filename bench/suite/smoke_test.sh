#!/usr/bin/env bash
# ctest bench_suite_scenes: the suite's generators at tiny sizes, and every scene they write
# loads and renders (16x16, 1 spp) with the triangle and emitter counts asked for.
# usage: smoke_test.sh TWINRAY WORK_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
twinray=$1 work=$2
rm -rf "$work"
mkdir -p "$work"

check() {  # check SCENE TRIANGLES ANALYTIC EMITTERS
  local counts
  counts=$(python3 "$here/gen.py" count "$1")
  [ "$counts" = "$2 $3 $4" ] ||
    { echo "$1: counted '$counts' (triangles analytic emitters), expected '$2 $3 $4'" && exit 1; }
  "$twinray" render "$1" -D width=16 -D height=16 -D spp=1 --threads 2 -o "${1%.xml}.exr" |
    grep -E '^twinray: 16x16, 1 spp, '
}

# 1000 asked: a 32-column grid of 16 rings gives 2 * 32 * 16 = 1024, in a box of 6 rectangles.
check "$(python3 "$here/gen.py" mesh "$work" --triangles 1000)" $((1024 + 12)) 0 1
# 10 triangles, one area emitter each, over a rectangle.
check "$(python3 "$here/gen.py" emitters "$work" --count 10)" 12 0 10
# The fixed geometry: 5 triangles, 2 of them emissive.
check "$(python3 "$here/gen.py" emitters "$work" --count 2 --triangles 5)" 7 0 2
check "$(python3 "$here/gen.py" envmap "$work" --width 16)" 2 4 1
