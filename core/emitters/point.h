// Mitsuba `point`: isotropic point light of radiant intensity I (W/sr); the irradiance-like
// arriving quantity at distance r is I / r^2 (pbrt-v4 §12.1, PointLight::SampleLi).
#ifndef TWINRAY_CORE_EMITTERS_POINT_H
#define TWINRAY_CORE_EMITTERS_POINT_H

#include "core/emitters/emitter_sample.h"
#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

INLINE EmitterSample sample_point_emitter(IN(Emitter) e, vec3 ref_p) {
  EmitterSample s = emitter_sample_failed();
  vec3 v = e.position - ref_p;
  float dist2 = dot(v, v);
  if (!(dist2 > 0.0f)) return s;
  s.dist = sqrt(dist2);
  s.d = v / s.dist;
  s.p = e.position;
  s.pdf = 1.0f;
  s.delta = 1u;
  s.weight = e.radiance / dist2;
  return s;
}

TR_NAMESPACE_END

#endif
