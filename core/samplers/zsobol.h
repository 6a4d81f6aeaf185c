// pbrt-v4's `zsobol` sampler (Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed.,
// §8.7.7 "Blue Noise Sobol Sampler"), after Ahmed & Wonka, "Screen-Space Blue-Noise Diffusion
// of Monte Carlo Sampling Error via Hierarchical Ordering of Pixels", SIGGRAPH Asia 2020.
//
// The pixels of the film are ordered along a Morton curve, and sample i of pixel (x, y) is
// point m = (morton(x, y) << log2 n) | i of one 2D Sobol sequence (van der Corput and Sobol's
// second dimension, core/samplers/ldsampler.h), n = sample_count a power of 2. Before the point
// is taken, each base-4 digit of m is permuted by one of the 24 permutations of {0, 1, 2, 3},
// chosen by a hash of the digits above it and of the dimension (and, when log2 n is odd, the
// lowest bit is flipped likewise). The permutation maps every aligned block of 4^k indices
// onto an aligned block, so a pixel's n samples stay a block of the sequence — a (0, log2 n, 2)
// -net — while neighbouring pixels receive disjoint, decorrelated blocks: the error spreads
// over the image as blue noise. Each coordinate is then Owen-scrambled by a hash of the
// dimension (Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4) 2020; the constants of
// pbrt-v4's FastOwenScrambler), which keeps the net property.
//
// As in pbrt-v4 the permutations and scrambles are shared by all pixels (that is what
// correlates them); unlike pbrt-v4 they also depend on the seed and on the pass (sample index
// / n), so a seed or a pass is an independent randomization of the whole image. A 2D draw
// consumes one dimension, as twinray's other samplers do (pbrt-v4 consumes two).
#ifndef TWINRAY_CORE_SAMPLERS_ZSOBOL_H
#define TWINRAY_CORE_SAMPLERS_ZSOBOL_H

#include "core/samplers/ldsampler.h"
#include "core/samplers/pcg4d.h"

TR_NAMESPACE_BEGIN

// 64-bit Morton index as (low, high) 32-bit words: GLSL has no 64-bit integers by default.
INLINE uvec2 zsobol_shift_right(uvec2 m, uint shift) {
  if (shift >= 32u) return uvec2(m.y >> (shift - 32u), 0u);
  if (shift == 0u) return m;
  return uvec2((m.x >> shift) | (m.y << (32u - shift)), m.y >> shift);
}

// Interleaves the 16 low bits of v with zeros: bit k goes to bit 2k.
INLINE uint zsobol_spread_bits(uint v) {
  v &= 0x0000ffffu;
  v = (v | (v << 8u)) & 0x00ff00ffu;
  v = (v | (v << 4u)) & 0x0f0f0f0fu;
  v = (v | (v << 2u)) & 0x33333333u;
  v = (v | (v << 1u)) & 0x55555555u;
  return v;
}

// The image of `digit` under permutation p of {0, 1, 2, 3}, p in [0, 24) read as a Lehmer code
// (factorial digits p / 6, p / 2 % 3, p % 2): every permutation once.
INLINE uint zsobol_permute_digit(uint p, uint digit) {
  uint remaining = 0x3210u;  // the values not yet placed, 4 bits each, in increasing order
  uint value = 0u;
  for (uint k = 0u; k <= digit; ++k) {
    uint choice = k == 0u ? p / 6u : (k == 1u ? p / 2u % 3u : (k == 2u ? p % 2u : 0u));
    uint shift = 4u * choice;
    value = (remaining >> shift) & 0xfu;
    uint below = remaining & ((1u << shift) - 1u);
    remaining = below | ((remaining >> (shift + 4u)) << shift);
  }
  return value;
}

// pbrt-v4's FastOwenScrambler: a hash of the reversed bits whose every output bit depends only
// on the input bits above it, i.e. a nested random permutation of the elementary intervals.
INLINE uint zsobol_owen_scramble(uint v, uint seed) {
  v = van_der_corput_bits(v);
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16u) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return van_der_corput_bits(v);
}

// The Sobol index of `index` (in [0, n)) of pixel (x, y), permuted for the dimension's key (its
// last two words). Only the low 32 bits are formed: the two Sobol dimensions used resolve 32
// bits, the digits above change no coordinate.
INLINE uint zsobol_sobol_index(Sampler s, uint x, uint y, uint index, uvec4 key) {
  uint log2n = uint(findMSB(s.sample_count));
  uint morton = (zsobol_spread_bits(y) << 1u) | zsobol_spread_bits(x);
  uvec2 m = uvec2((log2n < 32u ? morton << log2n : 0u) | index,
                  log2n == 0u ? 0u : morton >> (32u - log2n));
  uint odd = log2n & 1u;
  uint digits = s.resolution.y;
  uint result = 0u;
  for (uint i = min(digits, 16u + odd); i > odd; --i) {
    uint shift = 2u * (i - 1u) - odd;
    uint digit = zsobol_shift_right(m, shift).x & 3u;
    uvec2 higher = zsobol_shift_right(m, shift + 2u);
    uint p = pcg4d(uvec4(higher.x, higher.y, key.z, key.w)).x % 24u;
    result |= zsobol_permute_digit(p, digit) << shift;
  }
  if (odd != 0u) {
    uvec2 higher = zsobol_shift_right(m, 1u);
    result |= (m.x & 1u) ^ (pcg4d(uvec4(higher.x, higher.y, key.z, key.w)).x & 1u);
  }
  return result;
}

// key: pcg4d of (dimension, pass, seed) — x and y scramble the two coordinates, z and w choose
// the digit permutations.
INLINE float zsobol_1d(Sampler s, uint x, uint y, uint index, uvec4 key) {
  uint i = zsobol_sobol_index(s, x, y, index, key);
  return ld_bits_to_float(zsobol_owen_scramble(van_der_corput_bits(i), key.x));
}

INLINE vec2 zsobol_2d(Sampler s, uint x, uint y, uint index, uvec4 key) {
  uint i = zsobol_sobol_index(s, x, y, index, key);
  return vec2(ld_bits_to_float(zsobol_owen_scramble(van_der_corput_bits(i), key.x)),
              ld_bits_to_float(zsobol_owen_scramble(sobol_2_bits(i), key.y)));
}

TR_NAMESPACE_END

#endif
