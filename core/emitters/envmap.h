// Mitsuba `envmap`: an equirectangular radiance map at infinity.
//
// Lookup follows Mitsuba 3's latitude-longitude convention (src/emitters/envmap.cpp, v3.x):
// local direction (sin phi sin theta, cos theta, -cos phi sin theta) with theta = v pi and
// phi = 2 pi u; texel columns are centred at u = (i + 1/2) / W and wrap around; rows sit at
// v = j / (H - 1) (first and last row on the poles); values are interpolated bilinearly.
//
// Sampling: the scene's alias table picks a cell [i/W, (i+1)/W] x [j/H, (j+1)/H] of the
// (u, v) square with probability pmf (the loader makes it positive wherever the bilinear
// lookup can be), then a uniform point in it; with the spherical Jacobian
// dw = 2 pi^2 sin(theta) du dv (pbrt-v4 §12.5.2, eq. 12.9) the solid-angle density is
// pmf W H / (2 pi^2 sin theta).
#ifndef TWINRAY_CORE_EMITTERS_ENVMAP_H
#define TWINRAY_CORE_EMITTERS_ENVMAP_H

#include "core/alias.h"
#include "core/emitters/emitter_sample.h"
#include "core/scene_access.h"
#include "core/special_functions.h"
#include "core/transform.h"

TR_NAMESPACE_BEGIN

// Portable atan2/acos (core/special_functions.h): the lookup is identical on every backend.
INLINE vec2 envmap_direction_to_uv(vec3 d) {
  float u = atan2_portable(d.x, -d.z) * INV_TWO_PI;
  return vec2(u - floor(u), acos_portable(d.y) * INV_PI);
}

INLINE vec3 envmap_uv_to_direction(vec2 uv) {
  float theta = uv.y * PI;
  float phi = uv.x * 2.0f * PI;
  float st = sin(theta);
  return vec3(sin(phi) * st, cos(theta), -cos(phi) * st);
}

INLINE vec3 envmap_lookup(IN(Emitter) e, vec2 uv) {
  REF(Texture) tex = scene_texture(e.texture);
  float w = float(tex.width);
  float h = float(tex.height);
  float u = uv.x - 0.5f / w;
  u = (u - floor(u)) * w;
  float v = clamp(uv.y, 0.0f, 1.0f) * (h - 1.0f);
  uint x0 = min(uint(u), tex.width - 1u);
  uint y0 = min(uint(v), tex.height - 2u);
  float fx = u - float(x0);
  float fy = v - float(y0);
  uint x1 = x0 + 1u == tex.width ? 0u : x0 + 1u;
  uint row0 = tex.texel_offset + y0 * tex.width;
  uint row1 = row0 + tex.width;
  vec3 top = mix(vec3(scene_texel(row0 + x0)), vec3(scene_texel(row0 + x1)), fx);
  vec3 bottom = mix(vec3(scene_texel(row1 + x0)), vec3(scene_texel(row1 + x1)), fx);
  return mix(top, bottom, fy) * e.scale;
}

// Radiance arriving along -d_world, i.e. seen when looking in direction d_world.
INLINE vec3 eval_envmap_emitter(IN(Emitter) e, vec3 d_world) {
  vec3 d = transform_vector(e.to_local[0], e.to_local[1], e.to_local[2], d_world);
  return envmap_lookup(e, envmap_direction_to_uv(d));
}

INLINE float pdf_envmap_emitter(IN(Emitter) e, vec3 d_world) {
  REF(Texture) tex = scene_texture(e.texture);
  vec3 d = transform_vector(e.to_local[0], e.to_local[1], e.to_local[2], d_world);
  vec2 uv = envmap_direction_to_uv(d);
  // From the horizontal components: sqrt(1 - y^2) cancels to 0 within 3e-4 rad of the poles,
  // where the sampler still draws directions (the emitter chi-square test caught it).
  float sin_theta = length(vec2(d.x, d.z));
  if (!(sin_theta > 0.0f)) return 0.0f;
  uint i = min(uint(uv.x * float(tex.width)), tex.width - 1u);
  uint j = min(uint(uv.y * float(tex.height)), tex.height - 1u);
  float pmf = alias_pmf(e.alias_offset, j * tex.width + i);
  return pmf * float(tex.width) * float(tex.height) / (2.0f * PI * PI * sin_theta);
}

INLINE EmitterSample sample_envmap_emitter(IN(Emitter) e, vec3 ref_p, vec2 u_cell, vec2 u_pos) {
  EmitterSample s = emitter_sample_failed();
  REF(Texture) tex = scene_texture(e.texture);
  float pmf;
  uint cell = alias_sample(e.alias_offset, e.alias_count, u_cell, pmf);
  uint i = cell % tex.width;
  uint j = cell / tex.width;
  vec2 uv = vec2((float(i) + u_pos.x) / float(tex.width), (float(j) + u_pos.y) / float(tex.height));
  vec3 d_local = envmap_uv_to_direction(uv);
  float sin_theta = sin(uv.y * PI);
  if (!(sin_theta > 0.0f) || !(pmf > 0.0f)) return s;
  s.d = normalize(transform_vector(e.to_world[0], e.to_world[1], e.to_world[2], d_local));
  s.dist = FLOAT_MAX;
  s.p = ref_p + s.d;
  s.pdf = pmf * float(tex.width) * float(tex.height) / (2.0f * PI * PI * sin_theta);
  s.weight = envmap_lookup(e, uv) / s.pdf;
  return s;
}

TR_NAMESPACE_END

#endif
