// Mitsuba 3's `ldsampler` (src/samplers/ldsampler.cpp): a pass of n = 4^k samples takes the
// first n points of the (0,2)-sequence in base 2 (van der Corput, Sobol's second dimension),
// randomly permuted per (pixel, pass, dimension) and randomized by an XOR scramble (a random
// digital shift, Kollig & Keller 2002, "Efficient Multidimensional Sampling"), which keeps
// every elementary interval of volume 1/n holding exactly one point. Unlike Mitsuba 3.8,
// whose scramble is one per pixel and shared by all dimensions, the scramble here is drawn
// per dimension like the permutation.
#ifndef TWINRAY_CORE_SAMPLERS_LDSAMPLER_H
#define TWINRAY_CORE_SAMPLERS_LDSAMPLER_H

#include "core/samplers/permute.h"
#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

// Radical inverse in base 2 (van der Corput) as 32 fixed-point bits: the bits of i reversed.
INLINE uint van_der_corput_bits(uint i) {
  i = (i << 16u) | (i >> 16u);
  i = ((i & 0x00ff00ffu) << 8u) | ((i & 0xff00ff00u) >> 8u);
  i = ((i & 0x0f0f0f0fu) << 4u) | ((i & 0xf0f0f0f0u) >> 4u);
  i = ((i & 0x33333333u) << 2u) | ((i & 0xccccccccu) >> 2u);
  i = ((i & 0x55555555u) << 1u) | ((i & 0xaaaaaaaau) >> 1u);
  return i;
}

// Sobol's second dimension as 32 fixed-point bits: generator matrix rows v_{j+1} = v_j ^
// (v_j >> 1) from v_0 = 2^31 (Pascal's matrix mod 2; Kollig & Keller 2002, §2). Bit 31 - k of
// the result is the XOR of the bits j of i with C(j, k) odd, i.e. (Lucas's theorem) with the
// bits of k a subset of those of j: a superset transform over the 5 bits of the index, here
// with the bits still reversed (bit k).
INLINE uint sobol_2_reversed_bits(uint i) {
  i ^= (i >> 1u) & 0x55555555u;
  i ^= (i >> 2u) & 0x33333333u;
  i ^= (i >> 4u) & 0x0f0f0f0fu;
  i ^= (i >> 8u) & 0x00ff00ffu;
  i ^= (i >> 16u) & 0x0000ffffu;
  return i;
}

INLINE uint sobol_2_bits(uint i) { return van_der_corput_bits(sobol_2_reversed_bits(i)); }

INLINE float ld_bits_to_float(uint bits) { return float(bits >> 8u) * 5.9604645e-08f; }

// index: the sample's index within its pass; perm: the dimension's permutation seed;
// scramble: its XOR scramble bits.
INLINE float ldsampler_1d(Sampler s, uint index, uint perm, uint scramble) {
  uint i = permute_kensler(index, s.sample_count, perm);
  return ld_bits_to_float(van_der_corput_bits(i) ^ scramble);
}

INLINE vec2 ldsampler_2d(Sampler s, uint index, uint perm, uvec2 scramble) {
  uint i = permute_kensler(index, s.sample_count, perm);
  return vec2(ld_bits_to_float(van_der_corput_bits(i) ^ scramble.x),
              ld_bits_to_float(sobol_2_bits(i) ^ scramble.y));
}

TR_NAMESPACE_END

#endif
