// Mitsuba 3's `stratified` sampler (src/samplers/stratified.cpp): within a pass of
// n = r^2 samples, a 1D draw puts one point in each of the n strata [k/n, (k+1)/n) and a 2D
// draw one point in each cell of the r x r grid; the sample -> stratum assignment is a random
// permutation per (pixel, pass, dimension), so dimensions are independently shuffled.
// `jitter` places the point uniformly in its stratum, otherwise at its center.
#ifndef TWINRAY_CORE_SAMPLERS_STRATIFIED_H
#define TWINRAY_CORE_SAMPLERS_STRATIFIED_H

#include "core/samplers/permute.h"
#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

// index: the sample's index within its pass; perm: the dimension's permutation seed; j: the
// uniform jitter (used when s.jitter is set). Clamped below 1: (n - 1 + j) / n rounds up to 1
// for j close to 1.
INLINE float stratified_1d(Sampler s, uint index, uint perm, float j) {
  uint k = permute_kensler(index, s.sample_count, perm);
  float offset = s.jitter != 0u ? j : 0.5f;
  return min((float(k) + offset) * s.inv_sample_count, ONE_MINUS_EPSILON);
}

INLINE vec2 stratified_2d(Sampler s, uint index, uint perm, vec2 j) {
  uint k = permute_kensler(index, s.sample_count, perm);
  uint y = k / s.resolution.x;
  uint x = k - y * s.resolution.x;
  vec2 offset = s.jitter != 0u ? j : vec2(0.5f);
  vec2 p = (vec2(float(x), float(y)) + offset) * s.inv_resolution;
  return min(p, vec2(ONE_MINUS_EPSILON));
}

TR_NAMESPACE_END

#endif
