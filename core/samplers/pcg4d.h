// pcg4d, the 4D -> 4D hash behind every random number: Jarzynski & Olano, "Hash Functions for
// GPU Rendering", JCGT 9(3) 2020, §2.4 (passes TestU01 BigCrush as a 4D -> 4D hash).
#ifndef TWINRAY_CORE_SAMPLERS_PCG4D_H
#define TWINRAY_CORE_SAMPLERS_PCG4D_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

INLINE uvec4 pcg4d(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v = v ^ (v >> 16u);
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

TR_NAMESPACE_END

#endif
