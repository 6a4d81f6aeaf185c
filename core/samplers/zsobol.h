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
// dimension (core/samplers/owen_scramble.h), which keeps the net property.
//
// As in pbrt-v4 the permutations and scrambles are shared by all pixels (that is what
// correlates them); unlike pbrt-v4 they also depend on the seed and on the pass (sample index
// / n), so a seed or a pass is an independent randomization of the whole image. A 2D draw
// consumes one dimension, as twinray's other samplers do (pbrt-v4 consumes two).
#ifndef TWINRAY_CORE_SAMPLERS_ZSOBOL_H
#define TWINRAY_CORE_SAMPLERS_ZSOBOL_H

#include "core/samplers/ldsampler.h"
#include "core/samplers/lowbias32.h"
#include "core/samplers/owen_scramble.h"

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

// The image of `digit` under one of the 24 permutations of {0, 1, 2, 3}, chosen by the hash h.
// The permutations of the four 2-bit digits are exactly the affine maps x -> A x + c over
// GF(2)^2 (A one of the 6 invertible 2 x 2 binary matrices, c one of 4 shifts: 24 maps, all
// distinct): h's top 2 bits give c, its low 16 bits A (as floor(6 (h mod 2^16) / 2^16), which
// favours none by more than 6 / 2^16). ZSOBOL_MATRICES holds, 4 bits each (A 1 | A 2 << 2, A 0
// lowest), the images of 1 and 2 under each A: (1,2) (1,3) (2,1) (2,3) (3,1) (3,2).
const uint ZSOBOL_MATRICES = 0xb7e6d9u;
INLINE uint zsobol_permute_digit(uint h, uint digit) {
  uint a = (ZSOBOL_MATRICES >> (4u * (((h & 0xffffu) * 6u) >> 16u))) & 0xfu;
  uint image = ((digit & 1u) != 0u ? a & 3u : 0u) ^ ((digit & 2u) != 0u ? a >> 2u : 0u);
  return image ^ (h >> 30u);
}

// The hash that permutes the digit below `higher` (the digits above it) for the dimension's
// key.
INLINE uint zsobol_digit_hash(uvec2 higher, uvec4 key) {
  return lowbias32(((higher.x ^ key.z) * 0x9e3779b9u + key.w) ^ (higher.y * 0x85ebca6bu));
}

// The Morton code of pixel (x, y): the bits of x and y interleaved, x's lowest.
INLINE uint zsobol_morton(uint x, uint y) {
  return (zsobol_spread_bits(y) << 1u) | zsobol_spread_bits(x);
}

// The Sobol index of `index` (in [0, n)) of the pixel whose Morton code is `morton`, its digits
// permuted for the dimension's key (its last two words). Only the low 32 bits are formed: the two
// Sobol dimensions used resolve 32 bits, the digits above change no coordinate. Each digit's hash
// depends on the digits above it alone, so the digits are permuted independently of each other
// (no chain from one to the next).
INLINE uint zsobol_sobol_index(Sampler s, uint morton, uint index, uvec4 key) {
  uint log2n = uint(findMSB(s.sample_count));
  uvec2 m = uvec2((log2n < 32u ? morton << log2n : 0u) | index,
                  log2n == 0u ? 0u : morton >> (32u - log2n));
  uint odd = log2n & 1u;
  uint result = 0u;
  for (uint i = min(s.resolution.y, 16u + odd); i > odd; --i) {
    uint shift = 2u * (i - 1u) - odd;
    // Films up to 2^(16 - log2(n) / 2) pixels a side keep m within 32 bits.
    uvec2 higher = m.y == 0u ? uvec2((m.x >> shift) >> 2u, 0u) : zsobol_shift_right(m, shift + 2u);
    uint digit = (m.y == 0u ? m.x >> shift : zsobol_shift_right(m, shift).x) & 3u;
    result |= zsobol_permute_digit(zsobol_digit_hash(higher, key), digit) << shift;
  }
  if (odd != 0u) result |= (m.x ^ zsobol_digit_hash(zsobol_shift_right(m, 1u), key)) & 1u;
  return result;
}

// key: pcg4d of (dimension, pass, seed) — x and y scramble the two coordinates, z and w choose
// the digit permutations. The scrambler works on reversed bits: those of the van der Corput
// point are the index itself.
INLINE float zsobol_1d(Sampler s, uint morton, uint index, uvec4 key) {
  uint i = zsobol_sobol_index(s, morton, index, key);
  return ld_bits_to_float(van_der_corput_bits(owen_scramble_reversed(i, key.x)));
}

INLINE vec2 zsobol_2d(Sampler s, uint morton, uint index, uvec4 key) {
  uint i = zsobol_sobol_index(s, morton, index, key);
  uint sx = owen_scramble_reversed(i, key.x);
  uint sy = owen_scramble_reversed(sobol_2_reversed_bits(i), key.y);
  return vec2(ld_bits_to_float(van_der_corput_bits(sx)), ld_bits_to_float(van_der_corput_bits(sy)));
}

TR_NAMESPACE_END

#endif
