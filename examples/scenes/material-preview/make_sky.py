#!/usr/bin/env python3
"""Writes sky.exr: a small latitude-longitude environment map (Mitsuba 3 envmap convention) of a
clear sky with a sun, as an uncompressed scanline OpenEXR of half-float B, G, R channels
(OpenEXR file layout: openexr.com, "OpenEXR File Layout"). Python 3 standard library only.

    python3 make_sky.py [--width 128] [-o sky.exr]

Texel (i, j) covers u = (i + 0.5) / width, v = (j + 0.5) / height; its direction is Mitsuba's
envmap.cpp mapping: theta = pi v, phi = 2 pi u, d = (sin phi sin theta, cos theta,
-cos phi sin theta), +y up. The sky blends from a pale horizon to a blue zenith, the ground below
the horizon is a dull brown, and the sun is a disc of 3 degrees radius (smoothed over one texel)
at an elevation of about 34 degrees, towards -x and slightly -z (to the left of the default camera, a little behind the objects)."""
import argparse
import math
import struct

SUN_DIR = (-0.8, math.sin(math.radians(35)), -0.25)
SUN_RADIUS = math.radians(3.0)
SUN_RADIANCE = (300.0, 280.0, 240.0)


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def radiance(d, texel_angle):
    sun = normalize(SUN_DIR)
    elev = d[1]
    if elev >= 0.0:
        t = elev ** 0.5
        horizon, zenith = (0.55, 0.6, 0.7), (0.12, 0.22, 0.55)
        c = [h + (z - h) * t for h, z in zip(horizon, zenith)]
    else:
        c = [0.12, 0.1, 0.08]
    angle = math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(d, sun)))))
    # coverage of the sun's disc, linear over one texel around its edge
    w = min(1.0, max(0.0, (SUN_RADIUS + 0.5 * texel_angle - angle) / texel_angle))
    return [ci + w * s for ci, s in zip(c, SUN_RADIANCE)]


def attribute(name, type_name, data):
    return name.encode() + b"\0" + type_name.encode() + b"\0" + struct.pack("<i", len(data)) + data


def write_exr(path, width, height, pixels):
    chlist = b"".join(c + b"\0" + struct.pack("<iB3xii", 1, 0, 1, 1) for c in (b"B", b"G", b"R"))
    box = struct.pack("<4i", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2) +
              attribute("channels", "chlist", chlist + b"\0") +
              attribute("compression", "compression", b"\0") +
              attribute("dataWindow", "box2i", box) +
              attribute("displayWindow", "box2i", box) +
              attribute("lineOrder", "lineOrder", b"\0") +
              attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attribute("screenWindowCenter", "v2f", struct.pack("<2f", 0.0, 0.0)) +
              attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    line_bytes = 3 * 2 * width
    chunk = 8 + line_bytes
    first = len(header) + 8 * height
    offsets = b"".join(struct.pack("<Q", first + y * chunk) for y in range(height))
    with open(path, "wb") as f:
        f.write(header + offsets)
        for y in range(height):
            row = pixels[y]
            f.write(struct.pack("<ii", y, line_bytes))
            for channel in (2, 1, 0):  # B, G, R: channels sorted by name
                f.write(struct.pack(f"<{width}e", *(p[channel] for p in row)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--width", type=int, default=128)
    ap.add_argument("-o", "--output", default="sky.exr")
    a = ap.parse_args()
    width, height = a.width, a.width // 2
    texel_angle = math.pi / height
    pixels = []
    for j in range(height):
        theta = math.pi * (j + 0.5) / height
        row = []
        for i in range(width):
            phi = 2.0 * math.pi * (i + 0.5) / width
            d = (math.sin(phi) * math.sin(theta), math.cos(theta), -math.cos(phi) * math.sin(theta))
            row.append(radiance(d, texel_angle))
        pixels.append(row)
    write_exr(a.output, width, height, pixels)


if __name__ == "__main__":
    main()
