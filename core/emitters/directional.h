// Mitsuba `directional`: a distant source delivering irradiance E (W/m^2) on surfaces facing
// it, arriving along Emitter.direction (pbrt-v4 §12.4, DistantLight::SampleLi).
#ifndef TWINRAY_CORE_EMITTERS_DIRECTIONAL_H
#define TWINRAY_CORE_EMITTERS_DIRECTIONAL_H

#include "core/emitters/emitter_sample.h"
#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

INLINE EmitterSample sample_directional_emitter(IN(Emitter) e, vec3 ref_p) {
  EmitterSample s = emitter_sample_failed();
  s.d = -e.direction;
  s.dist = FLOAT_MAX;
  s.p = ref_p + s.d;
  s.pdf = 1.0f;
  s.delta = 1u;
  s.weight = e.radiance;
  return s;
}

TR_NAMESPACE_END

#endif
