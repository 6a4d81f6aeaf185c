// `sobol` (core/samplers/sobol.h): its generator matrices against Joe & Kuo's recurrence, their
// nibble table against the matrices, and the net properties its Owen scrambling must keep — every
// dimension a (0, 1)-sequence, the t-value of every projection the unscrambled sequence's, for
// draws within the table and past it.
#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <vector>

#include "core/rng.h"
#include "scenes/sampler.h"

namespace tr {
namespace {

// Dimensions (from 1) of new-joe-kuo-6.21201: degree s, coefficients a, initial m_1..m_s.
struct JoeKuoLine {
  uint d, s, a;
  std::vector<uint> m;
};

// Joe & Kuo (2008), §2: m_i = 2 a_1 m_(i-1) ^ 4 a_2 m_(i-2) ^ ... ^ 2^s m_(i-s) ^ m_(i-s);
// column k of the generator is m_(k+1) 2^(31-k), reversed in SOBOL_MATRICES.
TEST(SobolMatrices, FollowJoeKuosRecurrence) {
  const JoeKuoLine lines[] = {{2, 1, 0, {1}},
                              {3, 2, 1, {1, 3}},
                              {4, 3, 1, {1, 3, 1}},
                              {5, 3, 2, {1, 1, 1}},
                              {6, 4, 1, {1, 1, 3, 3}},
                              {7, 4, 4, {1, 3, 5, 13}},
                              {8, 5, 2, {1, 1, 5, 5, 17}},
                              {9, 5, 4, {1, 1, 5, 5, 5}},
                              {11, 5, 11, {1, 1, 5, 1, 1}},
                              {12, 5, 13, {1, 1, 1, 3, 11}},
                              {13, 5, 14, {1, 3, 5, 5, 31}},
                              {14, 6, 1, {1, 3, 3, 9, 7, 49}},
                              {15, 6, 13, {1, 1, 1, 15, 21, 21}}};
  for (const JoeKuoLine& line : lines) {
    std::vector<uint> m = line.m;
    for (uint i = line.s; i < SOBOL_COLUMNS; ++i) {
      uint v = m[i - line.s] ^ (m[i - line.s] << line.s);
      for (uint k = 1; k < line.s; ++k)
        if ((line.a >> (line.s - 1 - k)) & 1u) v ^= m[i - k] << k;
      m.push_back(v);
    }
    for (uint k = 0; k < SOBOL_COLUMNS; ++k)
      EXPECT_EQ(SOBOL_MATRICES[(line.d - 1) * SOBOL_COLUMNS + k],
                van_der_corput_bits(m[k] << (31 - k)))
          << "dimension " << line.d << " column " << k;
  }
  for (uint k = 0; k < SOBOL_COLUMNS; ++k)
    EXPECT_EQ(SOBOL_MATRICES[k], 1u << k) << "the first dimension is van der Corput's";
}

// Index bit k changes digits 1..k+1 of the point, digit k+1 always: upper triangular with a
// unit diagonal, which makes every dimension a (0, 1)-sequence.
TEST(SobolMatrices, AreUpperTriangularWithUnitDiagonal) {
  for (uint d = 0; d < SOBOL_DIMENSIONS; ++d)
    for (uint k = 0; k < SOBOL_COLUMNS; ++k) {
      const uint column = SOBOL_MATRICES[d * SOBOL_COLUMNS + k];
      EXPECT_EQ(column >> k, 1u) << "dimension " << d << " column " << k;
    }
}

// The draws' product of a pair of matrices with an index, by the nibble table, is the XOR of
// the columns of the index's bits: every pair, indices with bits in every nibble, and an index
// of a pass of 2^10 taking the 10 digits such a pass uses.
TEST(SobolMatrices, NibbleTableProductIsTheMatricesProduct) {
  for (uint d = 0; d < SOBOL_DIMENSIONS; d += 2)
    for (uint index : {0u, 1u, 5u, 0x9u, 0xf0u, 0x3a5u, 0xabcdeu, 0xffffffu}) {
      uvec2 expected(0u);
      for (uint k = 0; k < SOBOL_COLUMNS; ++k)
        if ((index >> k) & 1u)
          expected ^= uvec2(SOBOL_MATRICES[d * SOBOL_COLUMNS + k],
                            SOBOL_MATRICES[(d + 1) * SOBOL_COLUMNS + k]);
      EXPECT_EQ(sobol_reversed_bits(index, d, SOBOL_COLUMNS), expected)
          << "dimensions " << d << ", " << d + 1 << ", index " << index;
      if (index < 1024u) {
        EXPECT_EQ(sobol_reversed_bits(index, d, 10u), expected) << index;
      }
    }
}

Sampler sobol(uint n) {
  Scene scene;
  set_sampler(scene, SAMPLER_SOBOL, n, true);
  return scene.buffers.globals.sampler_params;
}

// The coordinates of sample i of a pass: two per draw (the draws' 2D points).
std::vector<std::vector<float>> pass_points(const Sampler& s, uint pixel, uint pass, uint seed,
                                            const std::vector<uint>& draws) {
  std::vector<std::vector<float>> points;
  for (uint i = 0; i < s.sample_count; ++i) {
    std::vector<float> p;
    for (uint draw : draws) {
      Rng r = rng_init_sampler(pixel, pass * s.sample_count + i, seed, s);
      r.dimension = draw;
      vec2 u = rng_next_2d(r);
      p.push_back(u.x);
      p.push_back(u.y);
    }
    points.push_back(p);
  }
  return points;
}

// The smallest t for which n = 2^m points are a (t, m, s)-net in base 2: every elementary
// interval prod [a_j 2^-d_j, (a_j + 1) 2^-d_j), sum d_j = m - t, holds 2^t of them.
uint t_value(const std::vector<std::vector<float>>& points, uint m) {
  const uint s = uint(points[0].size());
  for (uint t = 0; t <= m; ++t) {
    bool net = true;
    std::vector<uint> digits(s, 0);
    std::function<void(uint, uint)> each = [&](uint j, uint left) {
      if (!net) return;
      if (j + 1 == s) {
        digits[j] = left;
        std::set<std::vector<uint>> cells;
        for (const std::vector<float>& p : points) {
          std::vector<uint> cell(s);
          for (uint k = 0; k < s; ++k) cell[k] = uint(p[k] * float(1u << digits[k]));
          cells.insert(cell);
        }
        net = cells.size() == (1u << (m - t));
        return;
      }
      for (uint d = 0; d <= left; ++d) {
        digits[j] = d;
        each(j + 1, left - d);
      }
    };
    each(0, m - t);
    if (net) return t;
  }
  return m;
}

// The same point set unscrambled, straight from the matrices (n = 2^m).
std::vector<std::vector<float>> unscrambled(uint m, const std::vector<uint>& dimensions) {
  std::vector<std::vector<float>> points;
  for (uint i = 0; i < (1u << m); ++i) {
    std::vector<float> p;
    for (uint d : dimensions) {
      uvec2 pair = sobol_reversed_bits(i, d & ~1u, m);  // dimensions 2k and 2k + 1
      p.push_back(ld_bits_to_float(van_der_corput_bits((d & 1u) != 0u ? pair.y : pair.x)));
    }
    points.push_back(p);
  }
  return points;
}

TEST(SobolNets, OneDimensionalStrata) {
  for (uint n : {4u, 64u, 1024u}) {
    const Sampler s = sobol(n);
    for (uint draw : {0u, 1u, 5u, 63u, 64u, 65u, 200u}) {
      std::vector<std::vector<float>> points = pass_points(s, 1234u, 3u, 7u, {draw});
      for (uint c = 0; c < 2; ++c) {
        std::set<uint> strata;
        for (const std::vector<float>& p : points) strata.insert(uint(p[c] * float(n)));
        EXPECT_EQ(strata.size(), n) << "n " << n << " draw " << draw << " coordinate " << c;
      }
    }
  }
}

// Owen scrambling permutes elementary intervals: each projection keeps its t exactly, and the
// padded draws past the table (indices permuted) keep that of the dimensions they repeat.
TEST(SobolNets, ScramblingKeepsTheTValue) {
  const uint m = 8, n = 1u << m;
  const Sampler s = sobol(n);
  struct Projection {
    std::vector<uint> draws, dimensions;
  };
  const Projection projections[] = {
      {{0}, {0, 1}},          {{1}, {2, 3}},      {{2}, {4, 5}},  {{0, 1}, {0, 1, 2, 3}},
      {{1, 2}, {2, 3, 4, 5}}, {{63}, {126, 127}}, {{64}, {2, 3}}, {{100}, {74, 75}}};
  for (const Projection& pr : projections)
    for (uint pixel : {0u, 99u}) {
      uint expected = t_value(unscrambled(m, pr.dimensions), m);
      uint t = t_value(pass_points(s, pixel, 1u, 5u, pr.draws), m);
      EXPECT_EQ(t, expected) << "draw " << pr.draws[0] << " pixel " << pixel;
      if (pr.dimensions.size() == 2 && pr.dimensions[0] == 0) {
        EXPECT_EQ(t, 0u) << "film: (0, 2)";
      }
    }
}

}  // namespace
}  // namespace tr
