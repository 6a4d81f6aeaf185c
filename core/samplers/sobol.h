// `sobol`: each pixel's samples are the points of the Sobol sequence (Joe & Kuo's direction
// numbers, core/samplers/sobol_matrices.h), every coordinate Owen-scrambled by a hash of
// (pixel, pass, dimension, seed) (core/samplers/owen_scramble.h): randomized quasi-Monte
// Carlo as in Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4) 2020, §4, and pbrt-v4's
// SobolSample with its FastOwen randomization (Pharr, Jakob & Humphreys, "Physically Based
// Rendering", 4th ed., §8.7). The first 2^k samples of a pixel form a (t, k, s)-net in all
// dimensions at once (not only in pairs of them, as the padded samplers stratify), whose
// Owen scrambling keeps the net and makes each point uniform (Owen 1995), so a pixel's
// estimate is unbiased and a pass is an independent randomization.
//
// Draw number c of a sample (a 1D or 2D draw, core/rng.h) takes Sobol dimension 2c, or 2c and
// 2c + 1: the camera's film position is dimensions 0 and 1. Past the table (draw 64 on, deep
// in a path) the dimensions repeat from 2 with the pass's indices permuted by a hash of the
// draw (Kensler's permutation, core/samplers/permute.h), which decorrelates the repeat from
// its first use ("padding", pbrt-v4 §8.7.6).
//
// pbrt-v4's SobolSampler instead takes one sequence for the whole image (a pixel's samples
// are the points that fall in it) and leaves the two film dimensions unscrambled: a pixel's
// film positions are then the same for every seed, so seeds are not independent
// randomizations and an average over seeds is not an unbiased estimate of the pixel
// integral. Scrambling per pixel keeps both properties; `zsobol` is the variant whose
// pixels are correlated.
#ifndef TWINRAY_CORE_SAMPLERS_SOBOL_H
#define TWINRAY_CORE_SAMPLERS_SOBOL_H

#include "core/samplers/ldsampler.h"
#include "core/samplers/lowbias32.h"
#include "core/samplers/owen_scramble.h"
#include "core/samplers/permute.h"
#include "core/samplers/sobol_matrices.h"
#include "core/scene_access.h"

TR_NAMESPACE_BEGIN

// Point `index` (below 2^digits) of Sobol dimensions `dimension` and `dimension` + 1 (even),
// their digits reversed (bit j the 2^-(j+1) digit): the matrices' product with the index, four
// bits of the index a lookup (core/samplers/sobol_matrices.h).
INLINE uvec2 sobol_reversed_bits(uint index, uint dimension, uint digits) {
  uvec2 v = uvec2(0u);
  uint entry = (dimension / 2u) * SOBOL_NIBBLES * 16u;
  for (uint n = 0u; 4u * n < digits; ++n)
    v ^= scene_sobol_nibble(entry + 16u * n + ((index >> (4u * n)) & 15u));
  return v;
}

// The scramble seed of Sobol dimension `counter` of the pass whose key is `key` (at ~draw: the
// permutation of a padded draw): the counter hashed with the key, as SplitMix hashes its counter
// (Steele, Lea & Flood, "Fast Splittable Pseudorandom Number Generators", OOPSLA 2014), here
// through lowbias32 (an XOR of key and counter instead left neighbouring seeds correlated:
// Uniformity.ChiSquare in tests/samplers caught it).
INLINE uint sobol_seed(uint key, uint counter) { return lowbias32(key + counter * 0x9e3779b9u); }

INLINE float sobol_scramble(uint reversed, uint seed) {
  return ld_bits_to_float(van_der_corput_bits(owen_scramble_reversed(reversed, seed)));
}

// The first Sobol dimension of draw `draw`; past the table, `index` is permuted.
INLINE uint sobol_dimension(Sampler s, uint draw, uint key, INOUT(uint) index) {
  uint dimension = 2u * draw;
  if (dimension < SOBOL_DIMENSIONS) return dimension;
  index = permute_kensler(index, s.sample_count, sobol_seed(key, ~draw));
  return 2u + (dimension - 2u) % (SOBOL_DIMENSIONS - 2u);
}

// index: the sample's index within its pass; key: Rng.key, the hash of (pixel, pass, seed). A
// 1D draw is the first coordinate of the 2D draw.
INLINE vec2 sobol_2d(Sampler s, uint index, uint draw, uint key) {
  uint dimension = sobol_dimension(s, draw, key, index);
  uvec2 v = sobol_reversed_bits(index, dimension, uint(findMSB(s.sample_count)));
  return vec2(sobol_scramble(v.x, sobol_seed(key, 2u * draw)),
              sobol_scramble(v.y, sobol_seed(key, 2u * draw + 1u)));
}

INLINE float sobol_1d(Sampler s, uint index, uint draw, uint key) {
  uint dimension = sobol_dimension(s, draw, key, index);
  uint v = sobol_reversed_bits(index, dimension, uint(findMSB(s.sample_count))).x;
  return sobol_scramble(v, sobol_seed(key, 2u * draw));
}

TR_NAMESPACE_END

#endif
