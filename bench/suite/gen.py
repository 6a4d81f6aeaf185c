#!/usr/bin/env python3
"""Procedural scenes of the end-to-end benchmark suite (bench/suite/run.sh), as Mitsuba 3 XML.

  gen.py mesh OUT [--triangles N]   OUT/mesh_N.xml + OUT/mesh_N.ply: a displaced sphere of about
                                    N triangles (binary little-endian PLY) in a box with one
                                    rectangular area light
  gen.py emitters OUT [--count N] [--triangles T]
                                    OUT/emitters_N.xml + OUT/emitters_N/*.ply: N small emissive
                                    triangles (one PLY shape, hence one area emitter, each) of
                                    log-uniformly distributed power over a diffuse plane; with
                                    T (>= N): OUT/emitters_N_of_T.xml, T triangles whose places
                                    do not depend on N, the first N of them emissive, the rest
                                    black (the same geometry for every N)
  gen.py envmap OUT [--width W]     OUT/envmap.xml + OUT/envmap_sky.pfm: spheres on a plane lit
                                    only by an `envmap` (a procedural sky with a sun, W x W/2 PFM)
  gen.py count SCENE.xml            prints "TRIANGLES ANALYTIC_SHAPES EMITTERS" (count_scene)

Each scene takes -D spp, width, height, max_depth. Standard library only; deterministic (a
fixed seed per scene).
"""
import argparse
import math
import os
import random
import re
import struct
import sys
import xml.etree.ElementTree as ET
from array import array

SENSOR = """    <default name="spp" value="{spp}"/>
    <default name="width" value="{width}"/>
    <default name="height" value="{height}"/>
    <default name="max_depth" value="{max_depth}"/>

    <integrator type="path">
        <integer name="max_depth" value="$max_depth"/>
    </integrator>

    <sensor type="perspective">
        <float name="fov" value="{fov}"/>
        <transform name="to_world">
            <lookat origin="{origin}" target="{target}" up="0, 1, 0"/>
        </transform>
        <sampler type="independent">
            <integer name="sample_count" value="$spp"/>
        </sampler>
        <film type="hdrfilm">
            <integer name="width" value="$width"/>
            <integer name="height" value="$height"/>
            <rfilter type="box"/>
        </film>
    </sensor>
"""


def little_endian(a):
    if sys.byteorder != "little":
        a.byteswap()
    return a.tobytes()


def write_ply(path, positions, faces):
    """positions: array('f') of xyz; faces: array('i') of vertex index triples."""
    nv, nf = len(positions) // 3, len(faces) // 3
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"element vertex {nv}\nproperty float x\nproperty float y\nproperty float z\n"
              f"element face {nf}\nproperty list uchar int vertex_indices\nend_header\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(little_endian(positions))
        # Each face is a uchar 3 and three int32: packed a block of faces at a time.
        block = 4096
        for start in range(0, nf, block):
            n = min(block, nf - start)
            f.write(struct.pack("<" + "B3i" * n, *[v for k in range(start, start + n)
                                                   for v in (3, faces[3 * k], faces[3 * k + 1],
                                                             faces[3 * k + 2])]))


def sphere_grid(triangles):
    """A latitude-longitude grid of nu columns and rings = nv - 1 rings: 2 nu (nv - 1) triangles
    (nu per polar cap, 2 nu per band), nu about twice the rings so that cells are square-ish."""
    nu = max(3, round(math.sqrt(triangles)))
    rings = max(2, round(triangles / (2 * nu)))
    return nu, rings


def displaced_radius(theta, phi):
    # Three octaves of products of sines: a fixed, smooth, bumpy surface whose finest detail
    # still spans many triangles at 1e6.
    return 1.0 + (0.08 * math.sin(5 * theta) * math.sin(4 * phi) +
                  0.035 * math.sin(17 * theta + 1.0) * math.cos(13 * phi) +
                  0.012 * math.sin(53 * theta + 2.0) * math.sin(47 * phi + 0.5))


def gen_mesh(out, triangles):
    nu, rings = sphere_grid(triangles)
    pos = array("f")
    # Vertex 0 is the north pole, then rings k = 1..rings at theta = pi k / (rings + 1), each of
    # nu vertices, then the south pole.
    pos.extend((0.0, displaced_radius(0.0, 0.0), 0.0))
    for k in range(1, rings + 1):
        theta = math.pi * k / (rings + 1)
        st, ct = math.sin(theta), math.cos(theta)
        for j in range(nu):
            phi = 2 * math.pi * j / nu
            r = displaced_radius(theta, phi)
            pos.extend((r * st * math.cos(phi), r * ct, r * st * math.sin(phi)))
    south = 1 + rings * nu
    pos.extend((0.0, -displaced_radius(math.pi, 0.0), 0.0))

    def v(k, j):  # ring k (1-based), column j (wrapping)
        return 1 + (k - 1) * nu + (j % nu)

    # Winding: with p(theta, phi) = r (sin t cos p, cos t, sin t sin p), the outward normal is
    # dp/dphi x dp/dtheta, so a triangle runs (a, a's next column, a's next ring).
    faces = array("i")
    for j in range(nu):
        faces.extend((0, v(1, j + 1), v(1, j)))
    for k in range(1, rings):
        for j in range(nu):
            a, b, c, d = v(k, j), v(k, j + 1), v(k + 1, j), v(k + 1, j + 1)
            faces.extend((a, b, c, b, d, c))
    for j in range(nu):
        faces.extend((v(rings, j), v(rings, j + 1), south))
    n = len(faces) // 3
    name = f"mesh_{n}"
    write_ply(os.path.join(out, name + ".ply"), pos, faces)
    # A 4 x 3 x 4 box (floor at y = 0, open towards the camera), the sphere of radius about 1
    # on it, a 1 x 1 area light under the ceiling.
    xml = f"""<!-- bench/suite: a displaced sphere of {n} triangles (a {nu} x {rings} latitude-longitude
     grid, binary PLY) in a diffuse box lit by one rectangular area light. -->
<scene version="3.0.0">
{SENSOR.format(spp=16, width=256, height=256, max_depth=6, fov=45, origin="0, 1.5, 6.5",
               target="0, 1.2, 0")}
    <bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.7"/></bsdf>
    <shape type="ply">
        <string name="filename" value="{name}.ply"/>
        <transform name="to_world"><translate y="1.2"/></transform>
        <bsdf type="roughplastic">
            <rgb name="diffuse_reflectance" value="0.6, 0.35, 0.2"/>
            <float name="alpha" value="0.2"/>
        </bsdf>
    </shape>
    <shape type="rectangle"><!-- floor -->
        <transform name="to_world"><rotate x="1" angle="-90"/><scale x="2" y="1" z="2"/></transform>
        <ref id="white"/>
    </shape>
    <shape type="rectangle"><!-- ceiling -->
        <transform name="to_world"><rotate x="1" angle="90"/><scale x="2" y="1" z="2"/>
            <translate y="3"/></transform>
        <ref id="white"/>
    </shape>
    <shape type="rectangle"><!-- back -->
        <transform name="to_world"><scale x="2" y="1.5" z="1"/><translate y="1.5" z="-2"/></transform>
        <ref id="white"/>
    </shape>
    <shape type="rectangle"><!-- left, red -->
        <transform name="to_world"><rotate y="1" angle="90"/><scale x="1" y="1.5" z="2"/>
            <translate x="-2" y="1.5"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.63, 0.065, 0.05"/></bsdf>
    </shape>
    <shape type="rectangle"><!-- right, green -->
        <transform name="to_world"><rotate y="1" angle="-90"/><scale x="1" y="1.5" z="2"/>
            <translate x="2" y="1.5"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.14, 0.45, 0.091"/></bsdf>
    </shape>
    <shape type="rectangle"><!-- light -->
        <transform name="to_world"><rotate x="1" angle="90"/><scale value="0.5"/>
            <translate y="2.98"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.78"/></bsdf>
        <emitter type="area"><rgb name="radiance" value="25"/></emitter>
    </shape>
</scene>
"""
    path = os.path.join(out, name + ".xml")
    with open(path, "w") as f:
        f.write(xml)
    return path


def gen_emitters(out, count, triangles=None):
    rng = random.Random(15)
    fixed = triangles is not None
    total_shapes = triangles if fixed else count
    name = f"emitters_{count}_of_{triangles}" if fixed else f"emitters_{count}"
    folder = os.path.join(out, name)
    os.makedirs(folder, exist_ok=True)
    # Powers log-uniform over four decades, scaled so that all emitters together emit the same
    # 300 W whatever the count (the images stay comparable). A one-sided Lambertian emitter of
    # radiance L and area A emits pi L A.
    # Beyond 1000 triangles they shrink so that together they cover the same area (about a
    # quarter of the plane's, seen from above): more emitters, not a ceiling of them.
    side = 0.3 * min(1.0, math.sqrt(1000.0 / total_shapes))
    area = 0.5 * side * side
    powers = [10.0 ** rng.uniform(0.0, 4.0) for _ in range(count)]
    total = sum(powers)
    # With a fixed geometry the places come from their own generator, so that they do not
    # depend on the count of emitters.
    place_rng = random.Random(16) if fixed else rng
    shapes = []
    for i in range(total_shapes):
        x, y, z = (place_rng.uniform(-7, 7), place_rng.uniform(0.4, 2.5),
                   place_rng.uniform(-7, 7))
        a = place_rng.uniform(0, 2 * math.pi)
        ca, sa = math.cos(a), math.sin(a)
        # a, a + side * e1, a + side * e2 with e1 = (cos, 0, sin), e2 = (-sin, 0, cos): the
        # normal e1 x e2 = (0, -1, 0) faces the plane.
        pos = array("f", (x, y, z, x + side * ca, y, z + side * sa, x - side * sa, y, z + side * ca))
        write_ply(os.path.join(folder, f"{i}.ply"), pos, array("i", (0, 1, 2)))
        shape = f'    <shape type="ply"><string name="filename" value="{name}/{i}.ply"/><ref id="black"/>'
        if i < count:
            radiance = 300.0 * powers[i] / total / (math.pi * area)
            shape += (f'<emitter type="area"><rgb name="radiance" value="{radiance:.6g}"/>'
                      f'</emitter>')
        shapes.append(shape + "</shape>\n")
    what = (f"{triangles} small triangles, the first {count} of them emissive" if fixed else
            f"{count} emissive triangles")
    xml = f"""<!-- bench/suite: {what} (each its own PLY shape, so its own area
     emitter; Mitsuba's uniform emitter selection) of log-uniform power over four decades, 300 W
     in all, 0.4 to 2.5 above a 20 x 20 diffuse plane, facing it. -->
<scene version="3.0.0">
{SENSOR.format(spp=16, width=256, height=256, max_depth=4, fov=50, origin="0, 11, 13",
               target="0, 0, 0")}
    <bsdf type="diffuse" id="black"><rgb name="reflectance" value="0"/></bsdf>
    <shape type="rectangle">
        <transform name="to_world"><rotate x="1" angle="-90"/><scale value="10"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.6"/></bsdf>
    </shape>
{"".join(shapes)}</scene>
"""
    path = os.path.join(out, name + ".xml")
    with open(path, "w") as f:
        f.write(xml)
    return path


def sky(theta, phi):
    """A procedural sky (radiance, linear RGB) in direction (theta from +y, phi): a blue
    gradient, a warm horizon band, and a sun of 1.5 degrees' radius at 35 degrees' elevation."""
    sun_t, sun_p = math.radians(55.0), math.radians(60.0)
    cos_g = (math.sin(theta) * math.sin(sun_t) * math.cos(phi - sun_p) +
             math.cos(theta) * math.cos(sun_t))
    up = max(math.cos(theta), 0.0)
    if math.cos(theta) < 0.0:  # below the horizon: a dim ground colour
        r, g, b = 0.12, 0.1, 0.08
    else:
        h = math.exp(-8.0 * up)
        r, g, b = 0.25 + 0.6 * h, 0.45 + 0.45 * h, 0.95 + 0.1 * h
    if cos_g > math.cos(math.radians(1.5)):
        return 4000.0, 3600.0, 3000.0
    glow = 2.0 * max(cos_g, 0.0) ** 64
    return r + glow, g + glow, b + 0.7 * glow


def gen_envmap(out, width):
    height = width // 2
    data = array("f")
    # PFM stores rows bottom to top; a latitude-longitude map's top row is theta = 0. Mitsuba's
    # envmap maps u to phi and v to theta (src/emitters/envmap.cpp): pixel (i, j) from the top
    # looks along theta = pi (j + 0.5) / H, phi = 2 pi (i + 0.5) / W.
    for row in range(height):
        j = height - 1 - row
        theta = math.pi * (j + 0.5) / height
        for i in range(width):
            data.extend(sky(theta, 2 * math.pi * (i + 0.5) / width))
    with open(os.path.join(out, "envmap_sky.pfm"), "wb") as f:
        f.write(f"PF\n{width} {height}\n-1.0\n".encode("ascii"))  # negative scale: little-endian
        f.write(little_endian(data))
    xml = f"""<!-- bench/suite: four spheres (diffuse, rough gold, glass, rough plastic) on a diffuse
     plane, lit only by an envmap: envmap_sky.pfm, a {width} x {height} procedural sky with a sun. -->
<scene version="3.0.0">
{SENSOR.format(spp=16, width=384, height=216, max_depth=8, fov=40, origin="0, 1.6, 6",
               target="0, 0.45, 0")}
    <emitter type="envmap"><string name="filename" value="envmap_sky.pfm"/></emitter>
    <shape type="rectangle">
        <transform name="to_world"><rotate x="1" angle="-90"/><scale value="20"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.45"/></bsdf>
    </shape>
    <shape type="sphere"><point name="center" x="-1.65" y="0.5" z="0"/><float name="radius" value="0.5"/>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.7, 0.7, 0.7"/></bsdf></shape>
    <shape type="sphere"><point name="center" x="-0.55" y="0.5" z="0"/><float name="radius" value="0.5"/>
        <bsdf type="roughconductor"><string name="material" value="Au"/><float name="alpha" value="0.15"/></bsdf></shape>
    <shape type="sphere"><point name="center" x="0.55" y="0.5" z="0"/><float name="radius" value="0.5"/>
        <bsdf type="dielectric"/></shape>
    <shape type="sphere"><point name="center" x="1.65" y="0.5" z="0"/><float name="radius" value="0.5"/>
        <bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="0.1, 0.2, 0.6"/></bsdf></shape>
</scene>
"""
    path = os.path.join(out, "envmap.xml")
    with open(path, "w") as f:
        f.write(xml)
    return path


def count_scene(path):
    """(triangles, analytic shapes, emitters) of an XML scene as this suite uses them: mesh
    triangles from the files (OBJ faces fanned as twinray fans them, PLY face counts from the
    header, triangles assumed), 2 per rectangle, 12 per cube; analytic shapes (sphere, disk,
    cylinder) are counted apart; shapegroup/instance are not followed. Emitters: one per shape carrying an area emitter (twinray
    makes one emitter per shape, its triangles chosen by area within it) plus every other
    emitter. <include> is followed; $name takes its <default>."""
    defaults, ids, shapes = {}, {}, []
    triangles = analytic = emitters = 0

    def value(s):
        return re.sub(r"\$(\w+)", lambda m: defaults.get(m.group(1), m.group(0)), s)

    def mesh_triangles(file, kind):
        if kind == "obj":
            n = 0
            with open(file) as f:
                for line in f:
                    if line.startswith("f "):
                        n += len(line.split()) - 3
            return n
        with open(file, "rb") as f:
            for line in f:
                if line.startswith(b"element face"):
                    return int(line.split()[2])
                if line.startswith(b"end_header"):
                    return 0
        return 0

    def walk(root, base):
        nonlocal triangles, analytic, emitters
        for e in root:
            if e.tag == "default":
                defaults.setdefault(e.get("name"), e.get("value"))
            elif e.tag == "include":
                walk(ET.parse(os.path.join(base, value(e.get("filename")))).getroot(), base)
            elif e.tag == "emitter":
                if e.get("id"):
                    ids[e.get("id")] = e
                if e.get("type") != "area":
                    emitters += 1
            elif e.tag == "shape":
                kind = e.get("type")
                if kind in ("obj", "ply"):
                    file = [c.get("value") for c in e if c.get("name") == "filename"][0]
                    triangles += mesh_triangles(os.path.join(base, value(file)), kind)
                elif kind == "rectangle":
                    triangles += 2
                elif kind == "cube":
                    triangles += 12
                elif kind in ("sphere", "disk", "cylinder"):
                    analytic += 1
                shapes.append(e)

    walk(ET.parse(path).getroot(), os.path.dirname(os.path.abspath(path)))
    # After the walk: an emitter may be declared (with an id) after the shape that refers to it.
    for e in shapes:
        if any(c.tag == "emitter" or (c.tag == "ref" and c.get("id") in ids and
                                      ids[c.get("id")].get("type") == "area") for c in e):
            emitters += 1
    return triangles, analytic, emitters


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    m = sub.add_parser("mesh")
    m.add_argument("out")
    m.add_argument("--triangles", type=int, default=1000000)
    e = sub.add_parser("emitters")
    e.add_argument("out")
    e.add_argument("--count", type=int, default=100)
    e.add_argument("--triangles", type=int)
    v = sub.add_parser("envmap")
    v.add_argument("out")
    v.add_argument("--width", type=int, default=512)
    c = sub.add_parser("count")
    c.add_argument("scene")
    a = p.parse_args()
    if a.cmd == "count":
        print(*count_scene(a.scene))
        return
    if a.cmd == "mesh" and a.triangles < 8:
        p.error("--triangles must be at least 8")
    if a.cmd == "emitters" and a.count < 1:
        p.error("--count must be at least 1")
    if a.cmd == "emitters" and a.triangles is not None and a.triangles < a.count:
        p.error("--triangles must be at least --count")
    if a.cmd == "envmap" and a.width < 4:
        p.error("--width must be at least 4")
    os.makedirs(a.out, exist_ok=True)
    if a.cmd == "mesh":
        print(gen_mesh(a.out, a.triangles))
    elif a.cmd == "emitters":
        print(gen_emitters(a.out, a.count, a.triangles))
    else:
        print(gen_envmap(a.out, a.width))


if __name__ == "__main__":
    main()
