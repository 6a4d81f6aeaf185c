#!/usr/bin/env bash
# Command-line misuse exits with status 2 and a message; --help exits 0.
set -u
twinray=$1
"$twinray" render >/dev/null 2>&1; [ $? -eq 2 ] || { echo "render without a scene: expected 2"; exit 1; }
"$twinray" render x.xml --spp zero >/dev/null 2>&1; [ $? -eq 2 ] || { echo "--spp zero: expected 2"; exit 1; }
"$twinray" frobnicate >/dev/null 2>&1; [ $? -eq 2 ] || { echo "unknown verb: expected 2"; exit 1; }
"$twinray" render --help >/dev/null || { echo "render --help: expected 0"; exit 1; }
echo ok
