// What a backend's closest-hit query reports to the core.
#ifndef TWINRAY_CORE_HIT_H
#define TWINRAY_CORE_HIT_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

struct Hit {
  uint instance;      // Instance record index
  uint shape;         // global Shape index; NO_INDEX for a miss
  uint primitive;     // triangle index within the shape's mesh
  float t;            // ray parameter of the hit
  vec2 barycentrics;  // (b1, b2) of the triangle hit; unused for analytic shapes
  uint pad0;
  uint pad1;
};

INLINE Hit miss_hit() {
  Hit h;
  h.instance = NO_INDEX;
  h.shape = NO_INDEX;
  h.primitive = NO_INDEX;
  h.t = FLOAT_MAX;
  h.barycentrics = vec2(0.0f);
  h.pad0 = 0u;
  h.pad1 = 0u;
  return h;
}

TR_NAMESPACE_END

#endif
