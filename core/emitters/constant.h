// Mitsuba `constant`: uniform radiance from every direction, sampled uniformly on the sphere
// (pdf 1 / 4pi, pbrt-v4 §A.5.2).
#ifndef TWINRAY_CORE_EMITTERS_CONSTANT_H
#define TWINRAY_CORE_EMITTERS_CONSTANT_H

#include "core/emitters/emitter_sample.h"
#include "core/scene_types.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

INLINE EmitterSample sample_constant_emitter(IN(Emitter) e, vec3 ref_p, vec2 u) {
  EmitterSample s = emitter_sample_failed();
  s.d = square_to_uniform_sphere(u);
  s.dist = FLOAT_MAX;
  s.p = ref_p + s.d;
  s.pdf = INV_FOUR_PI;
  s.weight = e.radiance / s.pdf;
  return s;
}

INLINE float pdf_constant_emitter() { return INV_FOUR_PI; }

TR_NAMESPACE_END

#endif
