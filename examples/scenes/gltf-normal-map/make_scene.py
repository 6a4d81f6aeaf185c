#!/usr/bin/env python3
"""Writes the glTF 2.0 example scene of this folder: scene.gltf, scene.bin and its PNG textures.

A ground plane and a UV sphere, both with a bumpy tangent-space normal map (glTF 2.0 spec,
"Additional Textures": OpenGL convention, +Y toward the image's top), a base-colour texture and
a metallic-roughness texture (B = metallic, G = roughness; spec "Metallic-Roughness Material");
an emissive quad above them, a point light (KHR_lights_punctual) and a perspective camera.
Standard library only (struct, zlib for the PNGs), deterministic output.

    python3 make_scene.py [OUT_DIR]   (default: this script's folder)
"""
import json
import math
import os
import struct
import sys
import zlib

TEX = 64  # texture side, pixels


def png(path, width, height, pixels):
    """8-bit RGB PNG (ISO/IEC 15948): `pixels` rows of (r, g, b) tuples, top row first."""
    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    raw = b"".join(b"\x00" + bytes(v for p in row for v in p) for row in pixels)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def byte(x):
    return max(0, min(255, int(round(x * 255.0))))


def textures(out):
    # Height field of round bumps, 4 x 4 per texture; the normal is (-dh/dx, dh/dy, 1) with y
    # down the image, so that +Y (green) points toward the image's top (decreasing v).
    def height(x, y):
        return 0.5 * math.sin(2 * math.pi * 4 * x) * math.sin(2 * math.pi * 4 * y)

    normal, color, mr = [], [], []
    eps = 1.0 / TEX
    for j in range(TEX):
        nrow, crow, mrow = [], [], []
        for i in range(TEX):
            x, y = (i + 0.5) / TEX, (j + 0.5) / TEX
            dx = (height(x + eps, y) - height(x - eps, y)) / (2 * eps) * 0.05
            dy = (height(x, y + eps) - height(x, y - eps)) / (2 * eps) * 0.05
            n = (-dx, dy, 1.0)
            length = math.sqrt(sum(c * c for c in n))
            nrow.append(tuple(byte(0.5 * c / length + 0.5) for c in n))
            checker = (i // 8 + j // 8) % 2
            crow.append((230, 160, 60) if checker else (60, 120, 200))
            # R unused (occlusion), G = roughness, B = metallic (spec "Metallic-Roughness Material")
            mrow.append((255, byte(0.2 + 0.6 * (j / (TEX - 1))), 255 if checker else 0))
        normal.append(nrow)
        color.append(crow)
        mr.append(mrow)
    png(os.path.join(out, "normal.png"), TEX, TEX, normal)
    png(os.path.join(out, "base_color.png"), TEX, TEX, color)
    png(os.path.join(out, "metallic_roughness.png"), TEX, TEX, mr)


class Buffer:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def add(self, values, fmt, count, kind, component, target, minmax=False):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        for v in values:
            self.data += struct.pack("<" + fmt, *v) if isinstance(v, tuple) else struct.pack("<" + fmt, v)
        self.views.append({"buffer": 0, "byteOffset": offset,
                           "byteLength": len(self.data) - offset, "target": target})
        acc = {"bufferView": len(self.views) - 1, "componentType": component,
               "count": count, "type": kind}
        if minmax:
            acc["min"] = [min(v[k] for v in values) for k in range(3)]
            acc["max"] = [max(v[k] for v in values) for k in range(3)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def mesh(self, positions, normals, uvs, indices):
        a = {"POSITION": self.add(positions, "fff", len(positions), "VEC3", 5126, 34962, True),
             "NORMAL": self.add(normals, "fff", len(normals), "VEC3", 5126, 34962)}
        if uvs is not None:
            a["TEXCOORD_0"] = self.add(uvs, "ff", len(uvs), "VEC2", 5126, 34962)
        i = self.add(indices, "H", len(indices), "SCALAR", 5123, 34963)
        return a, i


def quad(size, uv_repeat):
    h = size / 2
    p = [(-h, 0.0, h), (h, 0.0, h), (h, 0.0, -h), (-h, 0.0, -h)]
    n = [(0.0, 1.0, 0.0)] * 4
    # u along +x, v along +z (toward the camera): the image's top is away from the viewer
    uv = [(0.0, uv_repeat), (uv_repeat, uv_repeat), (uv_repeat, 0.0), (0.0, 0.0)]
    return p, n, uv, [0, 1, 2, 0, 2, 3]


def sphere(radius, rings, segments):
    p, n, uv, idx = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            d = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            p.append(tuple(radius * c for c in d))
            n.append(d)
            uv.append((2.0 * s / segments, r / rings))
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return p, n, uv, idx


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    textures(out)
    buf = Buffer()
    plane_a, plane_i = buf.mesh(*quad(4.0, 2.0))
    sphere_a, sphere_i = buf.mesh(*sphere(0.7, 16, 32))
    lp, ln, _, li = quad(0.8, 1.0)
    light_a, light_i = buf.mesh([(x, y, z) for x, y, z in lp], [(0.0, -1.0, 0.0)] * 4, None,
                                [0, 2, 1, 0, 3, 2])
    with open(os.path.join(out, "scene.bin"), "wb") as f:
        f.write(buf.data)

    textured = {"baseColorTexture": {"index": 0},
                "metallicRoughnessTexture": {"index": 1}}
    gltf = {
        "asset": {"version": "2.0", "generator": "twinray examples/scenes/gltf-normal-map/make_scene.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
        "nodes": [
            {"name": "ground", "mesh": 0},
            {"name": "ball", "mesh": 1, "translation": [0.0, 0.7, 0.0],
             "rotation": [0.0, 0.3826834, 0.0, 0.9238795]},
            {"name": "panel", "mesh": 2, "translation": [-1.0, 2.5, 0.5]},
            {"name": "lamp", "translation": [1.5, 2.0, 1.5],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "camera", "camera": 0, "translation": [0.0, 1.6, 4.2],
             "rotation": [-0.1305262, 0.0, 0.0, 0.9914449]},
        ],
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.75, "aspectRatio": 1.5, "znear": 0.05}}],
        "meshes": [
            {"name": "ground", "primitives": [{"attributes": plane_a, "indices": plane_i, "material": 0}]},
            {"name": "ball", "primitives": [{"attributes": sphere_a, "indices": sphere_i, "material": 1}]},
            {"name": "panel", "primitives": [{"attributes": light_a, "indices": light_i, "material": 2}]},
        ],
        "materials": [
            {"name": "bumpy ground",
             "pbrMetallicRoughness": dict(textured, metallicFactor=1.0, roughnessFactor=1.0),
             "normalTexture": {"index": 2, "scale": 1.0}},
            {"name": "bumpy ball",
             "pbrMetallicRoughness": dict(textured, baseColorFactor=[1.0, 0.9, 0.8, 1.0],
                                          metallicFactor=0.8, roughnessFactor=0.9),
             "normalTexture": {"index": 2, "scale": 1.5}},
            {"name": "glowing panel",
             "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0},
             "emissiveFactor": [6.0, 5.5, 5.0]},
        ],
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0},
                     {"source": 2, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": "base_color.png"}, {"uri": "metallic_roughness.png"},
                   {"uri": "normal.png"}],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "color": [1.0, 0.95, 0.9], "intensity": 8.0}]}},
        "buffers": [{"uri": "scene.bin", "byteLength": len(buf.data)}],
        "bufferViews": buf.views,
        "accessors": buf.accessors,
    }
    with open(os.path.join(out, "scene.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
