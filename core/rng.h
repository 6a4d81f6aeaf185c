// Counter-based random numbers: every value is a pure function of
// (seed, pixel, sample index, dimension), so images do not depend on thread count, tiling or
// dispatch order, and the GPU draws exactly the numbers the CPU draws.
//
// Hash: pcg4d, Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3) 2020, §2.4;
// it passes TestU01 BigCrush as a 4D->4D hash. The dimension counter advances by one per
// hash, which yields four 32-bit values; rng_next_1d uses the first, rng_next_2d the first
// two, so consecutive calls never reuse a counter.
#ifndef TWINRAY_CORE_RNG_H
#define TWINRAY_CORE_RNG_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

struct Rng {
  uint pixel;         // linear pixel index
  uint sample_index;  // sample index within the pixel
  uint seed;
  uint dimension;  // next counter value
};

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

INLINE Rng rng_init(uint pixel, uint sample_index, uint seed) {
  Rng r;
  r.pixel = pixel;
  r.sample_index = sample_index;
  r.seed = seed;
  r.dimension = 0u;
  return r;
}

// Top 24 bits scaled by 2^-24: exactly representable, uniform on [0, 1).
INLINE float rng_to_unit_float(uint bits) { return float(bits >> 8u) * 5.9604645e-08f; }

INLINE uvec4 rng_next_bits(INOUT(Rng) r) {
  uvec4 h = pcg4d(uvec4(r.pixel, r.sample_index, r.dimension, r.seed));
  r.dimension += 1u;
  return h;
}

INLINE float rng_next_1d(INOUT(Rng) r) { return rng_to_unit_float(rng_next_bits(r).x); }

INLINE vec2 rng_next_2d(INOUT(Rng) r) {
  uvec4 h = rng_next_bits(r);
  return vec2(rng_to_unit_float(h.x), rng_to_unit_float(h.y));
}

TR_NAMESPACE_END

#endif
