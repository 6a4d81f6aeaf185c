#!/usr/bin/env bash
# The libraries twinray maps only when a run needs them (BENCHMARKS.md, "Memory"): the Vulkan
# loader (gpu_backend/vulkan_api.h), OpenEXR's C++ library (io/exr_read_module.cpp) and Assimp
# (scenes/assimp/) are not linked, a CPU render that writes EXR and PNG maps none of them, and a
# render that reads an EXR texture loads the EXR module. The loader's LD_DEBUG=files trace lists
# every library a process maps, linked or opened.
set -u
twinray=$1
scenes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "$1"; exit 1; }

needed=$(readelf -d "$twinray" | grep NEEDED)
for lib in libvulkan libOpenEXR-3 libIex libassimp; do
  ! grep -q "$lib" <<<"$needed" || fail "twinray is linked against $lib"
done

LD_DEBUG=files "$twinray" render "$scenes/cornell-box/cornell_box.xml" -D width=16 -D height=16 \
  --spp 1 -o "$work/box.exr" >/dev/null 2>"$work/box.trace" || fail "CPU render failed"
for lib in libvulkan libOpenEXR-3 libIex libtwinray_exr_read libassimp libtwinray_assimp; do
  ! grep -q "file=.*$lib" "$work/box.trace" || fail "a CPU render of the box mapped $lib"
done

LD_DEBUG=files "$twinray" render "$scenes/material-preview/material_preview.xml" -D width=16 \
  -D height=16 --spp 1 -o "$work/preview.exr" >/dev/null 2>"$work/preview.trace" ||
  fail "render of an EXR-textured scene failed"
grep -q "file=.*libtwinray_exr_read" "$work/preview.trace" ||
  fail "reading an EXR texture did not load the EXR module"
! grep -q "file=.*libvulkan" "$work/preview.trace" || fail "a CPU render mapped libvulkan"
echo ok
