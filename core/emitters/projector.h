// Mitsuba 3 `projector` (src/emitters/projector.cpp): a point light at the origin of to_world
// projecting its `irradiance` texture along local +z through a pinhole with Mitsuba's
// perspective projection (horizontal field of view fov_x, the texture's aspect). A local point
// (x, y, z), z > 0, reads the texture at
//   uv = (1/2 - cot(fov_x/2) x / (2 z),  1/2 - aspect cot(fov_x/2) y / (2 z)),
// lit only where uv lies in [0, 1]^2, and receives along the direction d from the light
//   irradiance(uv) pi scale / (z^2 (n . d)),   n = to_world (0, 0, 1),
// Mitsuba's normalization (the quantity a point light's I / r^2 is): a diffuse plane of albedo
// rho facing the projector at unit distance on its axis reflects radiance rho scale
// irradiance(uv).
#ifndef TWINRAY_CORE_EMITTERS_PROJECTOR_H
#define TWINRAY_CORE_EMITTERS_PROJECTOR_H

#include "core/emitters/emitter_sample.h"
#include "core/scene_types.h"
#include "core/texture.h"
#include "core/transform.h"

TR_NAMESPACE_BEGIN

INLINE EmitterSample sample_projector_emitter(IN(Emitter) e, vec3 ref_p) {
  EmitterSample s = emitter_sample_failed();
  vec3 p = transform_point(e.to_local[0], e.to_local[1], e.to_local[2], ref_p);
  if (!(p.z > 0.0f)) return s;
  vec2 uv = vec2(0.5f) - vec2(p.x, p.y) / p.z * vec2(e.cone.x, e.cone.y);
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) return s;
  vec3 v = e.position - ref_p;
  float dist2 = dot(v, v);
  if (!(dist2 > 0.0f)) return s;
  s.dist = sqrt(dist2);
  s.d = v / s.dist;
  vec3 irradiance = e.texture != NO_INDEX ? eval_texture(e.texture, uv) : e.radiance;
  s.p = e.position;
  s.pdf = 1.0f;
  s.delta = 1u;
  s.weight = irradiance * (PI * e.scale / (p.z * p.z * -dot(e.direction, s.d)));
  return s;
}

TR_NAMESPACE_END

#endif
