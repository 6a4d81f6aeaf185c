// Texture evaluation with Mitsuba 3's semantics (src/textures/bitmap.cpp, checkerboard.cpp,
// and Dr.Jit's Texture lookup): uv passes through `to_uv`; a bitmap texel (i, j) covers
// [i, i+1) x [j, j+1) in pos = uv * resolution, row j = 0 being the top row of the image;
// bilinear filtering interpolates the four texels around pos - 0.5, nearest takes
// floor(pos); out-of-range texel indices are wrapped by `wrap_mode`. A `mesh_attribute`
// texture reads the hit mesh's vertex or face data instead (Mitsuba's Mesh::eval_attribute),
// so BSDF parameters are evaluated at a TexCoord: the uv and, on meshes, the triangle hit.
#ifndef TWINRAY_CORE_TEXTURE_H
#define TWINRAY_CORE_TEXTURE_H

#include "core/scene_access.h"

TR_NAMESPACE_BEGIN

// Non-negative remainder of i / n (n > 0), written without `%` on negative operands, which
// GLSL leaves undefined.
INLINE int texture_mod(int i, int n) {
  int q = int(floor(float(i) / float(n)));
  return clamp(i - q * n, 0, n - 1);
}

// Dr.Jit WrapMode: repeat tiles, mirror reflects every other tile (period 2n), clamp holds
// the edge texel.
INLINE int texture_wrap(int i, int n, uint mode) {
  if (mode == WRAP_CLAMP) return clamp(i, 0, n - 1);
  bool mirror = mode != WRAP_REPEAT;
  int m = texture_mod(i, mirror ? 2 * n : n);
  return mirror && m >= n ? 2 * n - 1 - m : m;
}

// Where a texture is evaluated: the surface's uv and, on a mesh, the shape, the triangle and
// the barycentrics (b1, b2) of the hit, which mesh attributes interpolate.
struct TexCoord {
  vec2 uv;
  vec2 barycentrics;
  uint shape;  // NO_INDEX where no mesh was hit
  uint primitive;
};

INLINE TexCoord tex_coord_mesh(vec2 uv, uint shape, uint primitive, vec2 barycentrics) {
  TexCoord c;
  c.uv = uv;
  c.barycentrics = barycentrics;
  c.shape = shape;
  c.primitive = primitive;
  return c;
}

// A point known only by its uv (no mesh attributes).
INLINE TexCoord tex_coord(vec2 uv) { return tex_coord_mesh(uv, NO_INDEX, 0u, vec2(0.0f)); }

INLINE vec3 texture_texel(IN(Texture) t, int i, int j) {
  ivec2 size = ivec2(int(t.width), int(t.height));
  ivec2 p = ivec2(i, j);
  // One wrap per axis in a loop: every lookup of every textured parameter is inlined into the
  // shader, so the lookup is kept to one call site of each helper.
  UNROLL for (int a = 0; a < 2; ++a) p[a] = texture_wrap(p[a], size[a], t.wrap_mode);
  return vec3(scene_texel(t.texel_offset + uint(p.y) * t.width + uint(p.x)));
}

INLINE vec2 texture_apply_to_uv(IN(Texture) t, vec2 uv) {
  vec3 h = vec3(uv.x, uv.y, 1.0f);
  return vec2(dot(vec3(t.to_uv[0]), h), dot(vec3(t.to_uv[1]), h));
}

// The texels a lookup at st reads: with bilinear filtering the four around pos = st * resolution
// - 0.5, v[0] = (i, j), v[1] = (i + 1, j), v[2] = (i, j + 1), v[3] = (i + 1, j + 1) for
// (i, j) = floor(pos), and the weights w1 = pos - (i, j) of the second ones; with nearest
// filtering v[0] alone, at floor(st * resolution).
struct TexelQuad {
  vec3 v[4];
  vec2 w1;
};

INLINE TexelQuad texture_texels(IN(Texture) t, vec2 st) {
  bool nearest = t.filter_mode == FILTER_NEAREST;
  vec2 res = vec2(float(t.width), float(t.height));
  vec2 pos = nearest ? st * res : st * res - vec2(0.5f);
  vec2 p0 = floor(pos);
  TexelQuad q;
  q.w1 = pos - p0;
  int count = nearest ? 1 : 4;
  UNROLL for (int k = 0; k < 4; ++k) {
    if (k < count) q.v[k] = texture_texel(t, int(p0.x) + (k & 1), int(p0.y) + (k >> 1));
  }
  return q;
}

INLINE vec3 eval_texture(uint texture, vec2 uv) {
  REF(Texture) t = scene_texture(texture);
  vec2 st = texture_apply_to_uv(t, uv);
  if (TR_HAS_TEXTURE(TEXTURE_CHECKERBOARD) && t.type == TEXTURE_CHECKERBOARD) {
    // Mitsuba checkerboard: color0 where both fractional parts lie on the same side of 1/2.
    bool mx = st.x - floor(st.x) > 0.5f;
    bool my = st.y - floor(st.y) > 0.5f;
    return mx == my ? vec3(t.color0) : vec3(t.color1);
  }
  TexelQuad q = texture_texels(t, st);
  if (t.filter_mode == FILTER_NEAREST) return q.v[0];
  vec2 w0 = vec2(1.0f) - q.w1;
  return w0.y * (w0.x * q.v[0] + q.w1.x * q.v[1]) + q.w1.y * (w0.x * q.v[2] + q.w1.x * q.v[3]);
}

// Value i of a mesh attribute of `dim` (1 or 3) values per element starting at `offset` in the
// attribute buffer; a single channel is broadcast, as Mitsuba's eval turns it into a spectrum.
INLINE vec3 mesh_attribute_value(uint offset, uint dim, uint i) {
  uint first = offset + dim * i;
  vec3 v;
  UNROLL for (uint k = 0u; k < 3u; ++k) v[k] =
      uintBitsToFloat(scene_attribute(first + min(k, dim - 1u)));
  return v;
}

// Mitsuba `mesh_attribute` (src/textures/mesh_attribute.cpp; Mesh::interpolate_attribute in
// include/mitsuba/render/mesh.h): a vertex_* attribute is interpolated barycentrically as
// v0 b0 + (v1 b1 + v2 b2), a face_* attribute is constant over its triangle; both times
// `scale`. The mesh's table (Shape.attribute_table) holds, per attribute slot, the offset of
// its values and their count per element; the loader checks that every mesh a mesh_attribute
// texture can be evaluated on has the attribute, with 1 or 3 values (1 for scalar parameters).
INLINE vec3 eval_mesh_attribute(IN(Texture) t, TexCoord c) {
  REF(Shape) s = scene_shape(c.shape);
  uint entry = s.attribute_table + 2u * t.attribute_slot;
  uint offset = scene_attribute(entry);
  uint dim = scene_attribute(entry + 1u);
  bool per_face = t.attribute_per_face != 0u;
  uint base = s.first_index + 3u * c.primitive;
  vec3 v[3];
  uint count = per_face ? 1u : 3u;
  UNROLL for (uint k = 0u; k < 3u; ++k) {
    if (k < count)
      v[k] = mesh_attribute_value(offset, dim, per_face ? c.primitive : scene_index(base + k));
  }
  float b1 = c.barycentrics.x;
  float b2 = c.barycentrics.y;
  vec3 value = per_face ? v[0] : v[0] * (1.0f - b1 - b2) + (v[1] * b1 + v[2] * b2);
  return value * t.color0.x;
}

// A constant, or the texture lookup when the value is textured.
INLINE vec3 eval_textured(TexturedValue v, TexCoord c) {
  if (TR_HAS_TEXTURE(TEXTURE_MESH_ATTRIBUTE) && v.texture != NO_INDEX) {
    REF(Texture) t = scene_texture(v.texture);
    if (t.type == TEXTURE_MESH_ATTRIBUTE) return eval_mesh_attribute(t, c);
  }
  if ((TR_HAS_TEXTURE(TEXTURE_BITMAP) || TR_HAS_TEXTURE(TEXTURE_CHECKERBOARD)) &&
      v.texture != NO_INDEX)
    return eval_texture(v.texture, c.uv);
  return v.value;
}

INLINE vec3 eval_textured(TexturedValue v, vec2 uv) { return eval_textured(v, tex_coord(uv)); }

// Mitsuba's Texture::eval_1_grad of a bitmap (src/textures/bitmap.cpp): the uv gradient of the
// bilinear interpolation of the (scalar) texels, zero with nearest filtering. Like Mitsuba, the
// texel-space partials go through the transpose of to_uv's linear part and are then scaled by
// the resolution per component (exact for diagonal to_uv).
INLINE vec2 eval_texture_1_grad(uint texture, vec2 uv) {
  REF(Texture) t = scene_texture(texture);
  if (t.filter_mode == FILTER_NEAREST) return vec2(0.0f);
  vec2 res = vec2(float(t.width), float(t.height));
  TexelQuad q = texture_texels(t, texture_apply_to_uv(t, uv));
  vec2 w1 = q.w1;
  vec2 w0 = vec2(1.0f) - w1;
  float f00 = q.v[0].x;
  float f10 = q.v[1].x;
  float f01 = q.v[2].x;
  float f11 = q.v[3].x;
  vec2 df_xy =
      vec2(w0.y * (f10 - f00) + w1.y * (f11 - f01), w0.x * (f01 - f00) + w1.x * (f11 - f10));
  vec2 df_uv = vec2(t.to_uv[0].x * df_xy.x + t.to_uv[1].x * df_xy.y,
                    t.to_uv[0].y * df_xy.x + t.to_uv[1].y * df_xy.y);
  return res * df_uv;
}

TR_NAMESPACE_END

#endif
