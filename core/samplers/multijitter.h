// Mitsuba 3's `multijitter` sampler (src/samplers/multijitter.cpp), Kensler's correlated
// multi-jittered sampling (Pixar Technical Memo 13-01, 2013, §3): a pass of n = rx * ry
// samples fills an rx x ry grid, one point per cell, and within the cells the points also
// form an n-rooks pattern (one point in each of the n columns 1/n wide and each of the n rows
// 1/n high): in cell (x, y) the point sits in sub-column permute(y) of ry and sub-row
// permute(x) of rx. 1D draws are stratified in n strata as `stratified`'s.
#ifndef TWINRAY_CORE_SAMPLERS_MULTIJITTER_H
#define TWINRAY_CORE_SAMPLERS_MULTIJITTER_H

#include "core/samplers/stratified.h"

TR_NAMESPACE_BEGIN

// perm: three independent permutation seeds of the dimension (cells, sub-columns, sub-rows).
INLINE vec2 multijitter_2d(Sampler s, uint index, uvec3 perm, vec2 j) {
  uint k = permute_kensler(index, s.sample_count, perm.x);
  uint y = k / s.resolution.x;
  uint x = k - y * s.resolution.x;
  uint sub_x = permute_kensler(y, s.resolution.y, perm.y);
  uint sub_y = permute_kensler(x, s.resolution.x, perm.z);
  vec2 offset = s.jitter != 0u ? j : vec2(0.5f);
  PRECISE vec2 p =
      vec2((float(x) + (float(sub_x) + offset.x) * s.inv_resolution.y) * s.inv_resolution.x,
           (float(y) + (float(sub_y) + offset.y) * s.inv_resolution.x) * s.inv_resolution.y);
  return min(p, vec2(ONE_MINUS_EPSILON));
}

TR_NAMESPACE_END

#endif
