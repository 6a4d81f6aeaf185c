#!/usr/bin/env python3
"""Writes a UV sphere of radius 1 at the origin as a binary little-endian PLY with smooth
(per-vertex) normals, the normal of a unit sphere being its position.

    python3 make_sphere.py [--rings N] [--segments M] [-o sphere.ply]

Poles are single vertices joined to the first and last rings by triangle fans; between rings
each quad is split into two triangles. Faces are wound counter-clockwise seen from outside,
so the geometric normal (Mitsuba: cross(p1 - p0, p2 - p0)) points outwards."""
import argparse
import math
import struct


def sphere(rings, segments):
    verts = [(0.0, 1.0, 0.0)]
    for i in range(1, rings):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2.0 * math.pi * j / segments
            verts.append((math.sin(theta) * math.cos(phi), math.cos(theta),
                          -math.sin(theta) * math.sin(phi)))
    verts.append((0.0, -1.0, 0.0))
    south = len(verts) - 1

    def ring(i, j):  # vertex of ring i (1 .. rings-1), segment j (mod segments)
        return 1 + (i - 1) * segments + j % segments

    faces = []
    for j in range(segments):
        faces.append((0, ring(1, j), ring(1, j + 1)))
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b = ring(i, j), ring(i, j + 1)
            c, d = ring(i + 1, j), ring(i + 1, j + 1)
            faces.append((a, c, d))
            faces.append((a, d, b))
    for j in range(segments):
        faces.append((south, ring(rings - 1, j + 1), ring(rings - 1, j)))
    return verts, faces


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rings", type=int, default=32)
    ap.add_argument("--segments", type=int, default=64)
    ap.add_argument("-o", "--output", default="sphere.ply")
    a = ap.parse_args()
    if a.rings < 2 or a.segments < 3:
        ap.error("need at least 2 rings and 3 segments")
    verts, faces = sphere(a.rings, a.segments)
    header = ("ply\nformat binary_little_endian 1.0\n"
              "comment UV sphere, radius 1, written by make_sphere.py\n"
              f"element vertex {len(verts)}\n"
              "property float x\nproperty float y\nproperty float z\n"
              "property float nx\nproperty float ny\nproperty float nz\n"
              f"element face {len(faces)}\n"
              "property list uchar int vertex_indices\nend_header\n")
    with open(a.output, "wb") as f:
        f.write(header.encode("ascii"))
        for v in verts:
            f.write(struct.pack("<6f", *v, *v))
        for t in faces:
            f.write(struct.pack("<B3i", 3, *t))


if __name__ == "__main__":
    main()
