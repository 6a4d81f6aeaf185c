// Mitsuba 3's `orthogonal` sampler (src/samplers/orthogonal.cpp; Jarosz et al., "Orthogonal
// Array Sampling for Monte Carlo Rendering", EGSR 2019): the rows of Bose's orthogonal array
// OA(p^2, p + 1, p, 2) (Bose 1938; Jarosz et al. 2019 §4.2), p prime, one row per sample of a
// pass, the row order a random permutation per (pixel, pass) shared by every dimension. Column
// j gives the stratum (of p) of coordinate j, its partner column j xor 1 the sub-stratum (of
// p): any two columns hold every pair of symbols once (strength 2), so each coordinate is a
// Latin hypercube of p^2 strata and a 2D draw, columns 2d and 2d + 1 at dimension counter d,
// is a correlated multi-jittered p x p pattern (Kensler 2013). Each column's symbols are
// permuted per (pixel, pass, dimension), as Mitsuba permutes them per dimension. Columns past
// p repeat earlier ones' symbols (their index is taken mod p, as in Mitsuba's Bose scheme);
// their own symbol permutations keep every sample uniform in all dimensions.
#ifndef TWINRAY_CORE_SAMPLERS_ORTHOGONAL_H
#define TWINRAY_CORE_SAMPLERS_ORTHOGONAL_H

#include "core/samplers/permute.h"
#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

// Symbol of row i (0 <= i < p^2) in column j of Bose's array: with i = p a0 + a1, column 0
// holds a0, column 1 a1, column j >= 2 a0 + (j - 1) a1 mod p.
INLINE uint bose_symbol(uint row, uint column, uint p) {
  uint a0 = row / p;
  uint a1 = row - a0 * p;
  if (column == 0u) return a0;
  if (column == 1u) return a1;
  return (a0 + ((column - 1u) % p) * a1) % p;
}

// Coordinate of column `column` for OA row `row`: perm.x permutes the column's symbols (the
// stratum), perm.y its partner's (the sub-stratum); j: the uniform jitter.
INLINE float orthogonal_coordinate(Sampler s, uint row, uint column, uvec2 perm, float j) {
  uint p = s.resolution.x;
  uint stratum = permute_kensler(bose_symbol(row, column, p), p, perm.x);
  uint sub_stratum = permute_kensler(bose_symbol(row, column ^ 1u, p), p, perm.y);
  float offset = s.jitter != 0u ? j : 0.5f;
  PRECISE float x =
      (float(stratum) + (float(sub_stratum) + offset) * s.inv_resolution.x) * s.inv_resolution.x;
  return min(x, ONE_MINUS_EPSILON);
}

// row_perm: the pass's row permutation seed; perm: the dimension's four symbol permutation
// seeds (x stratum, x sub-stratum, y stratum, y sub-stratum).
INLINE float orthogonal_1d(Sampler s, uint index, uint dimension, uint row_perm, uvec4 perm,
                           float j) {
  uint row = permute_kensler(index, s.sample_count, row_perm);
  return orthogonal_coordinate(s, row, 2u * dimension, uvec2(perm.x, perm.y), j);
}

INLINE vec2 orthogonal_2d(Sampler s, uint index, uint dimension, uint row_perm, uvec4 perm,
                          vec2 j) {
  uint row = permute_kensler(index, s.sample_count, row_perm);
  return vec2(orthogonal_coordinate(s, row, 2u * dimension, uvec2(perm.x, perm.y), j.x),
              orthogonal_coordinate(s, row, 2u * dimension + 1u, uvec2(perm.z, perm.w), j.y));
}

TR_NAMESPACE_END

#endif
