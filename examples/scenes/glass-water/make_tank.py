#!/usr/bin/env python3
"""Writes the meshes of an open glass tank partly filled with water, one ASCII PLY per optical
interface, so that each can carry its own dielectric (Mitsuba's dielectric takes int_ior on the
side opposite the normal and ext_ior on the side the normal points to):

  tank_glass_air.ply    glass | air:   outer walls and bottom, the rim, inner walls above the water
  tank_water_glass.ply  water | glass: inner walls below the water and the inner bottom
  tank_water_air.ply    water | air:   the water surface

Normals point from the first medium into the second. The tank stands on y = 0, centred on the
y axis; sizes in metres:

    python3 make_tank.py [--width 0.8] [--depth 0.5] [--height 0.6] [--wall 0.03] [--water 0.42]
"""
import argparse


def quad(faces, verts, corners, normal):
    """Adds corners (a planar quad in cyclic order) as two triangles wound so that
    cross(p1 - p0, p2 - p0) points along normal."""
    p0, p1, p2 = corners[0], corners[1], corners[2]
    e1 = [b - a for a, b in zip(p0, p1)]
    e2 = [b - a for a, b in zip(p0, p2)]
    n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
    if sum(a * b for a, b in zip(n, normal)) < 0:
        corners = corners[::-1]
    base = len(verts)
    verts.extend(corners)
    faces.append((base, base + 1, base + 2))
    faces.append((base, base + 2, base + 3))


def box_sides(faces, verts, hx, hz, y0, y1, outward):
    """The four vertical walls x = +-hx, z = +-hz between y0 and y1, normals pointing away from
    the y axis if outward, else towards it."""
    s = 1 if outward else -1
    quad(faces, verts, [(hx, y0, -hz), (hx, y0, hz), (hx, y1, hz), (hx, y1, -hz)], (s, 0, 0))
    quad(faces, verts, [(-hx, y0, -hz), (-hx, y0, hz), (-hx, y1, hz), (-hx, y1, -hz)], (-s, 0, 0))
    quad(faces, verts, [(-hx, y0, hz), (hx, y0, hz), (hx, y1, hz), (-hx, y1, hz)], (0, 0, s))
    quad(faces, verts, [(-hx, y0, -hz), (hx, y0, -hz), (hx, y1, -hz), (-hx, y1, -hz)], (0, 0, -s))


def horizontal(faces, verts, x0, x1, z0, z1, y, up):
    quad(faces, verts, [(x0, y, z0), (x1, y, z0), (x1, y, z1), (x0, y, z1)], (0, 1 if up else -1, 0))


def write_ply(path, verts, faces, what):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\n")
        f.write(f"comment {what}; written by make_tank.py\n")
        f.write(f"element vertex {len(verts)}\n")
        f.write("property float x\nproperty float y\nproperty float z\n")
        f.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for v in verts:
            f.write("%.6g %.6g %.6g\n" % v)
        for t in faces:
            f.write("3 %d %d %d\n" % t)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--width", type=float, default=0.8)
    ap.add_argument("--depth", type=float, default=0.5)
    ap.add_argument("--height", type=float, default=0.6)
    ap.add_argument("--wall", type=float, default=0.03)
    ap.add_argument("--water", type=float, default=0.42)
    a = ap.parse_args()
    ox, oz, h, t, w = a.width / 2, a.depth / 2, a.height, a.wall, a.water
    ix, iz = ox - t, oz - t
    if not (ix > 0 and iz > 0 and t < w < h):
        ap.error("need wall < width/2, wall < depth/2 and wall < water < height")

    v, f = [], []
    box_sides(f, v, ox, oz, 0.0, h, True)
    horizontal(f, v, -ox, ox, -oz, oz, 0.0, False)
    horizontal(f, v, -ox, ox, iz, oz, h, True)  # rim, front strip
    horizontal(f, v, -ox, ox, -oz, -iz, h, True)  # back strip
    horizontal(f, v, -ox, -ix, -iz, iz, h, True)  # left strip
    horizontal(f, v, ix, ox, -iz, iz, h, True)  # right strip
    box_sides(f, v, ix, iz, w, h, False)
    write_ply("tank_glass_air.ply", v, f, "glass-air interface, normals into the air")

    v, f = [], []
    box_sides(f, v, ix, iz, t, w, True)
    horizontal(f, v, -ix, ix, -iz, iz, t, False)
    write_ply("tank_water_glass.ply", v, f, "water-glass interface, normals into the glass")

    v, f = [], []
    horizontal(f, v, -ix, ix, -iz, iz, w, True)
    write_ply("tank_water_air.ply", v, f, "water surface, normal into the air")


if __name__ == "__main__":
    main()
