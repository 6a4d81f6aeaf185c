// Mitsuba 3 `spot` (src/emitters/spot.cpp): a point light at the origin of to_world emitting
// along its local +z with radiant intensity I (W/sr), times a falloff in the angle theta from
// that axis,
//   falloff(theta) = 1                                          theta <= beam_width
//                  = (cutoff - theta) / (cutoff - beam_width)   beam_width < theta < cutoff
//                  = 0                                          otherwise
// (Mitsuba 3.8's linear ramp in the angle), and, with a `texture`, times the texture at
// uv = 1/2 + 1/2 (x, y) / (z tan(cutoff)) of the local direction (x, y, z): the cone's
// projection onto the plane z = 1, the cutoff circle inscribed in the unit square.
#ifndef TWINRAY_CORE_EMITTERS_SPOT_H
#define TWINRAY_CORE_EMITTERS_SPOT_H

#include "core/emitters/emitter_sample.h"
#include "core/scene_types.h"
#include "core/special_functions.h"
#include "core/texture.h"
#include "core/transform.h"

TR_NAMESPACE_BEGIN

// Falloff towards the local (not necessarily unit) direction d. Mitsuba takes theta as
// acos(cos theta); atan2(|d.xy|, d.z) is the same angle without acos's loss near the axis,
// and its portable form keeps the ramp identical on every backend (near the cutoff the ramp
// magnifies any difference in theta).
INLINE float spot_falloff(IN(Emitter) e, vec3 d) {
  float cos_theta = d.z / length(d);
  if (!(cos_theta > e.cone.x)) return 0.0f;
  if (cos_theta >= e.cone.y) return 1.0f;
  float theta = atan2_portable(length(vec2(d.x, d.y)), d.z);
  return (e.cone.z - theta) * e.cone.w;
}

INLINE vec2 spot_uv(IN(Emitter) e, vec3 d) {
  return vec2(0.5f) + 0.5f * vec2(d.x, d.y) / (d.z * e.tan_cutoff);
}

INLINE EmitterSample sample_spot_emitter(IN(Emitter) e, vec3 ref_p) {
  EmitterSample s = emitter_sample_failed();
  vec3 v = e.position - ref_p;
  float dist2 = dot(v, v);
  if (!(dist2 > 0.0f)) return s;
  float dist = sqrt(dist2);
  vec3 d = v / dist;
  vec3 d_local = transform_vector(e.to_local[0], e.to_local[1], e.to_local[2], -d);
  float falloff = spot_falloff(e, d_local);
  if (!(falloff > 0.0f)) return s;
  vec3 intensity = e.radiance;
  if (e.texture != NO_INDEX) intensity *= eval_texture(e.texture, spot_uv(e, d_local));
  s.dist = dist;
  s.d = d;
  s.p = e.position;
  s.pdf = 1.0f;
  s.delta = 1u;
  s.weight = intensity * (falloff / dist2);
  return s;
}

TR_NAMESPACE_END

#endif
