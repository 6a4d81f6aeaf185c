// Result of sampling a direction towards an emitter from a reference point.
#ifndef TWINRAY_CORE_EMITTERS_EMITTER_SAMPLE_H
#define TWINRAY_CORE_EMITTERS_EMITTER_SAMPLE_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

struct EmitterSample {
  vec3 p;       // sampled point on the emitter (unused for infinite emitters)
  float pdf;    // solid-angle density at the reference point (delta: the discrete probability);
                // 0 marks a failed sample
  vec3 n;       // emitter surface normal at p; zero for points and infinite emitters
  float dist;   // distance to p; FLOAT_MAX for infinite emitters
  vec3 d;       // unit direction from the reference point towards the emitter
  uint delta;   // 1 for point and directional emitters (no MIS partner)
  vec3 weight;  // emitted radiance arriving along -d, divided by pdf
  uint emitter;
};

INLINE EmitterSample emitter_sample_failed() {
  EmitterSample s;
  s.p = vec3(0.0f);
  s.pdf = 0.0f;
  s.n = vec3(0.0f);
  s.dist = 0.0f;
  s.d = vec3(0.0f, 0.0f, 1.0f);
  s.delta = 0u;
  s.weight = vec3(0.0f);
  s.emitter = NO_INDEX;
  return s;
}

TR_NAMESPACE_END

#endif
