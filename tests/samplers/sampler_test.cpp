// The stratified samplers (core/samplers/, drawn through core/rng.h): Mitsuba's sample_count
// rounding (zsobol: pbrt-v4's), each sampler's stratification property within a pass,
// chi-square uniformity of the marginal 1D and 2D distributions, and faster convergence than
// `independent`.
#include "scenes/sampler.h"

#include <gtest/gtest.h>
#include <twinray_validation.h>

#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "core/rng.h"

namespace tr {
namespace {

// A film of 640 x 480 (zsobol orders its pixels).
Sampler make(uint type, uint requested, bool jitter = true) {
  Scene scene;
  scene.buffers.globals.camera.width = 640;
  scene.buffers.globals.camera.height = 480;
  set_sampler(scene, type, requested, jitter);
  return scene.buffers.globals.sampler_params;
}

float draw_1d(const Sampler& s, uint pixel, uint index, uint seed, uint dimension) {
  Rng r = rng_init_sampler(pixel, index, seed, s);
  r.dimension = dimension;
  return rng_next_1d(r);
}

vec2 draw_2d(const Sampler& s, uint pixel, uint index, uint seed, uint dimension) {
  Rng r = rng_init_sampler(pixel, index, seed, s);
  r.dimension = dimension;
  return rng_next_2d(r);
}

const uint kStratifiedTypes[] = {SAMPLER_STRATIFIED, SAMPLER_LDSAMPLER, SAMPLER_MULTIJITTER,
                                 SAMPLER_ORTHOGONAL, SAMPLER_ZSOBOL,    SAMPLER_SOBOL};

// zsobol's pixels share one randomization: its independent randomizations are seeds.
bool randomized_by_seed(const Sampler& s) { return s.type == SAMPLER_ZSOBOL; }

TEST(Permute, IsABijectionForAnyLength) {
  for (uint n : {1u, 2u, 3u, 5u, 16u, 17u, 100u, 256u, 1000u, 4097u})
    for (uint p : {0u, 1u, 0x9e3779b9u, 0xdeadbeefu, 12345u}) {
      std::set<uint> image;
      for (uint i = 0; i < n; ++i) {
        uint k = permute_kensler(i, n, p);
        ASSERT_LT(k, n);
        image.insert(k);
      }
      EXPECT_EQ(image.size(), n) << "n " << n << " p " << p;
    }
}

// src/samplers/*.cpp set_sample_count in Mitsuba 3.8.
TEST(SampleCount, RoundsAsMitsuba) {
  struct Rounding {
    uint type, requested, rendered;
  };
  const Rounding table[] = {
      {SAMPLER_INDEPENDENT, 10, 10},  {SAMPLER_STRATIFIED, 1, 1},      {SAMPLER_STRATIFIED, 2, 4},
      {SAMPLER_STRATIFIED, 10, 16},   {SAMPLER_STRATIFIED, 16, 16},    {SAMPLER_STRATIFIED, 17, 25},
      {SAMPLER_LDSAMPLER, 1, 4},  // the grid starts at 2 x 2
      {SAMPLER_LDSAMPLER, 5, 16},     {SAMPLER_LDSAMPLER, 16, 16},     {SAMPLER_LDSAMPLER, 17, 64},
      {SAMPLER_LDSAMPLER, 25, 64},    {SAMPLER_LDSAMPLER, 1000, 1024}, {SAMPLER_MULTIJITTER, 1, 1},
      {SAMPLER_MULTIJITTER, 2, 2},                                    // 1 row of 2
      {SAMPLER_MULTIJITTER, 5, 6},                                    // 2 rows of 3
      {SAMPLER_MULTIJITTER, 10, 12},                                  // 3 rows of 4
      {SAMPLER_MULTIJITTER, 16, 16},  {SAMPLER_ORTHOGONAL, 1, 4},     // the smallest prime is 2
      {SAMPLER_ORTHOGONAL, 5, 9},     {SAMPLER_ORTHOGONAL, 10, 25},   // 4 is not prime
      {SAMPLER_ORTHOGONAL, 16, 25},   {SAMPLER_ORTHOGONAL, 50, 121},  // 8, 9 and 10 are not prime
      {SAMPLER_ORTHOGONAL, 289, 289}, {SAMPLER_ZSOBOL, 1, 1},          {SAMPLER_ZSOBOL, 3, 4},
      {SAMPLER_ZSOBOL, 16, 16},       {SAMPLER_ZSOBOL, 17, 32},  // pbrt-v4: powers of 2
      {SAMPLER_SOBOL, 1, 1},          {SAMPLER_SOBOL, 3, 4},           {SAMPLER_SOBOL, 1000, 1024},
  };
  for (const Rounding& r : table)
    EXPECT_EQ(rounded_sample_count(r.type, r.requested), r.rendered)
        << sampler_name(r.type) << " " << r.requested;
  EXPECT_THROW(rounded_sample_count(SAMPLER_STRATIFIED, (1u << 24) + 1u), SceneError);
}

TEST(SampleCount, SaysWhenItRounds) {
  Scene scene;
  set_sampler(scene, SAMPLER_STRATIFIED, 10, true);
  EXPECT_EQ(scene.spp, 16u);
  EXPECT_EQ(scene.sample_count_note, "stratified: sample_count 10 rounded up to 16, as Mitsuba");
  set_sample_count(scene, 25);
  EXPECT_EQ(scene.spp, 25u);
  EXPECT_EQ(scene.sample_count_note, "");
  set_sampler(scene, SAMPLER_INDEPENDENT, 10, true);
  EXPECT_EQ(scene.spp, 10u);
  EXPECT_EQ(scene.buffers.globals.sampler_params.sample_count, 1u) << "no passes: one record";
  set_sampler(scene, SAMPLER_MULTIJITTER, 10, false);
  EXPECT_EQ(scene.buffers.globals.sampler_params.resolution, uvec2(4u, 3u));
  EXPECT_EQ(scene.buffers.globals.sampler_params.jitter, 0u);
  scene.buffers.globals.camera.width = 300;
  scene.buffers.globals.camera.height = 520;
  set_sampler(scene, SAMPLER_ZSOBOL, 10, true);
  EXPECT_EQ(scene.sample_count_note, "zsobol: sample_count 10 rounded up to 16, as pbrt-v4");
  // width, log2 of 1024 (520 rounded up to a power of 2) + log4 of 16
  EXPECT_EQ(scene.buffers.globals.sampler_params.resolution, uvec2(300u, 12u));
  set_sample_count(scene, 32);
  EXPECT_EQ(scene.buffers.globals.sampler_params.resolution, uvec2(300u, 13u)) << "ceil(log4 32)";
  scene.buffers.globals.camera.width = 65537;
  EXPECT_THROW(set_sample_count(scene, 32), SceneError);
}

TEST(Independent, DrawsTheHashAsBefore) {
  Sampler s = make(SAMPLER_INDEPENDENT, 16);
  for (uint i = 0; i < 100; ++i) {
    Rng a = rng_init(i * 7u, i, 3u), b = rng_init_sampler(i * 7u, i, 3u, s);
    uvec4 h = pcg4d(uvec4(i * 7u, i, 0u, 3u));
    EXPECT_EQ(rng_next_1d(b), rng_to_unit_float(h.x));
    EXPECT_EQ(rng_next_1d(a), rng_to_unit_float(h.x));
    EXPECT_EQ(rng_next_2d(a), rng_next_2d(b));
    EXPECT_EQ(b.dimension, 2u);
  }
}

// Within each pass (samples k n .. k n + n - 1 of a pixel), for each dimension: the property
// each sampler guarantees.
void expect_stratified(uint type, uint requested, bool jitter) {
  Sampler s = make(type, requested, jitter);
  const uint n = s.sample_count;
  const uvec2 res = s.resolution;
  for (uint pixel : {0u, 1u, 4711u})
    for (uint pass : {0u, 1u, 5u})
      for (uint dim : {0u, 1u, 7u}) {
        SCOPED_TRACE("type " + std::to_string(type) + " n " + std::to_string(n) + " pixel " +
                     std::to_string(pixel) + " pass " + std::to_string(pass) + " dim " +
                     std::to_string(dim) + (jitter ? "" : " no jitter"));
        std::set<uint> strata_1d, cells, columns, rows;
        std::vector<vec2> points;
        for (uint i = 0; i < n; ++i) {
          float x = draw_1d(s, pixel, pass * n + i, 9u, dim);
          ASSERT_TRUE(x >= 0.0f && x < 1.0f);
          strata_1d.insert(uint(x * float(n)));
          vec2 p = draw_2d(s, pixel, pass * n + i, 9u, dim);
          ASSERT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f);
          points.push_back(p);
          columns.insert(uint(p.x * float(n)));
          rows.insert(uint(p.y * float(n)));
          if (type != SAMPLER_LDSAMPLER && type != SAMPLER_ZSOBOL && type != SAMPLER_SOBOL)
            cells.insert(uint(p.y * float(res.y)) * res.x + uint(p.x * float(res.x)));
        }
        EXPECT_EQ(strata_1d.size(), n) << "1D: one point per stratum of 1/n";
        if (type == SAMPLER_STRATIFIED) {
          EXPECT_EQ(cells.size(), n) << "one point per grid cell";
        }
        if (type == SAMPLER_MULTIJITTER || type == SAMPLER_ORTHOGONAL) {
          EXPECT_EQ(cells.size(), n) << "one point per grid cell";
          EXPECT_EQ(columns.size(), n) << "n-rooks: one point per column 1/n wide";
          EXPECT_EQ(rows.size(), n) << "n-rooks: one point per row 1/n high";
        }
        // sobol: the film's dimensions (Sobol's first two, draw 0); other pairs have t > 0.
        if (type == SAMPLER_LDSAMPLER || type == SAMPLER_ZSOBOL ||
            (type == SAMPLER_SOBOL && dim == 0)) {
          // (0, m, 2)-net in base 2, n = 2^m: every elementary interval 2^-a x 2^-(m - a).
          uint m = 0;
          while ((1u << m) < n) ++m;
          for (uint a = 0; a <= m; ++a) {
            std::set<uint> intervals;
            for (vec2 p : points)
              intervals.insert((uint(p.x * float(1u << a)) << (m - a)) |
                               uint(p.y * float(1u << (m - a))));
            EXPECT_EQ(intervals.size(), n) << "elementary intervals 2^-" << a << " x 2^-" << m - a;
          }
        }
      }
}

// orthogonal: the 1D draws at two dimension counters d < e are OA columns 2d and 2e; while
// both are at most p, each pair of their strata (of p) holds one sample (strength 2).
void expect_strength_two(uint requested) {
  Sampler s = make(SAMPLER_ORTHOGONAL, requested);
  const uint n = s.sample_count, p = s.resolution.x;
  for (uint pixel : {0u, 77u})
    for (uint pass : {0u, 3u})
      for (uint d = 0; 2 * d <= p; ++d)
        for (uint e = d + 1; 2 * e <= p; ++e) {
          std::set<uint> pairs;
          for (uint i = 0; i < n; ++i) {
            float x = draw_1d(s, pixel, pass * n + i, 9u, d);
            float y = draw_1d(s, pixel, pass * n + i, 9u, e);
            pairs.insert(uint(x * float(p)) * p + uint(y * float(p)));
          }
          EXPECT_EQ(pairs.size(), n) << "p " << p << " dimensions " << d << ", " << e;
        }
}

TEST(Stratification, Stratified) {
  for (uint requested : {1u, 4u, 10u, 16u, 64u, 256u}) {
    expect_stratified(SAMPLER_STRATIFIED, requested, true);
    expect_stratified(SAMPLER_STRATIFIED, requested, false);
  }
}

TEST(Stratification, Ldsampler) {
  for (uint requested : {4u, 16u, 64u, 256u, 1024u})
    expect_stratified(SAMPLER_LDSAMPLER, requested, true);
}

TEST(Stratification, Multijitter) {
  for (uint requested : {1u, 2u, 5u, 10u, 16u, 64u, 100u, 250u}) {
    expect_stratified(SAMPLER_MULTIJITTER, requested, true);
    expect_stratified(SAMPLER_MULTIJITTER, requested, false);
  }
}

TEST(Stratification, Sobol) {
  for (uint requested : {1u, 2u, 8u, 16u, 32u, 256u, 1024u})
    expect_stratified(SAMPLER_SOBOL, requested, true);
}

TEST(Stratification, Zsobol) {
  for (uint requested : {1u, 2u, 8u, 16u, 32u, 256u, 1024u})
    expect_stratified(SAMPLER_ZSOBOL, requested, true);
}

// zsobol spreads the error as blue noise: the pixels of an aligned 2^k x 2^k block of the film
// hold consecutive blocks of one sequence, so their first samples (one per pixel) together are
// a (0, 2k, 2)-net, at every dimension.
TEST(Stratification, ZsobolNeighbouringPixelsTogether) {
  Sampler s = make(SAMPLER_ZSOBOL, 1);
  for (uint k : {1u, 2u, 3u})
    for (uvec2 corner : {uvec2(0u), uvec2(8u, 16u), uvec2(600u, 472u)})
      for (uint dim : {0u, 1u, 9u}) {
        const uint side = 1u << k, m = 2u * k;
        std::vector<vec2> points;
        for (uint y = 0; y < side; ++y)
          for (uint x = 0; x < side; ++x)
            points.push_back(draw_2d(s, (corner.y + y) * 640u + corner.x + x, 0u, 5u, dim));
        for (uint a = 0; a <= m; ++a) {
          std::set<uint> intervals;
          for (vec2 p : points)
            intervals.insert((uint(p.x * float(1u << a)) << (m - a)) |
                             uint(p.y * float(1u << (m - a))));
          EXPECT_EQ(intervals.size(), points.size())
              << "block " << side << " at " << corner.x << ", " << corner.y << " dim " << dim
              << ": elementary intervals 2^-" << a << " x 2^-" << m - a;
        }
      }
}

TEST(Stratification, Orthogonal) {
  for (uint requested : {4u, 9u, 25u, 49u, 121u, 289u}) {
    expect_stratified(SAMPLER_ORTHOGONAL, requested, true);
    expect_stratified(SAMPLER_ORTHOGONAL, requested, false);
    expect_strength_two(requested);
  }
}

// Chi-square goodness of fit of one sample's marginal distribution: sample `index` of many
// pixels (independent randomizations of the pass) must be uniform in 1D, in 2D, and jointly
// uniform across two consecutive 1D dimensions (the dimensions' permutations are
// independent). Significance 1% over all cases, Sidak-corrected per case.
struct UniformityCase {
  uint type;
  uint requested;
  uint index;
  uint dimension;
};

// p-values of the 1D draw, the 2D draw and a pair of consecutive 1D draws of sample `index` at
// dimension `dimension`, over 200000 pixels (zsobol: 200000 seeds of pixel 4711).
std::array<double, 3> uniformity_p_values(const Sampler& s, uint index, uint dimension) {
  const uint kPixels = 200000, kBins1d = 100, kBins2d = 20;
  std::vector<double> h1(kBins1d, 0.0), h2(kBins2d * kBins2d, 0.0), hpair(kBins2d * kBins2d, 0.0);
  for (uint k = 0; k < kPixels; ++k) {
    const uint pixel = randomized_by_seed(s) ? 4711u : k, seed = randomized_by_seed(s) ? k : 17u;
    float x = draw_1d(s, pixel, index, seed, dimension);
    h1[uint(x * kBins1d)] += 1.0;
    vec2 p = draw_2d(s, pixel, index, seed, dimension);
    h2[uint(p.y * kBins2d) * kBins2d + uint(p.x * kBins2d)] += 1.0;
    Rng r = rng_init_sampler(pixel, index, seed, s);
    r.dimension = dimension;
    float u = rng_next_1d(r), v = rng_next_1d(r);
    hpair[uint(v * kBins2d) * kBins2d + uint(u * kBins2d)] += 1.0;
  }
  auto p_value = [&](const std::vector<double>& h) {
    double expected = double(kPixels) / double(h.size()), statistic = 0.0;
    for (double o : h) statistic += (o - expected) * (o - expected) / expected;
    return twinray::validation::chi_square_p_value(statistic, int(h.size()) - 1);
  };
  return {p_value(h1), p_value(h2), p_value(hpair)};
}

TEST(Uniformity, ChiSquare) {
  std::vector<UniformityCase> cases;
  for (uint type : kStratifiedTypes)
    for (uint requested : {16u, 64u})
      for (uint index : {0u, 5u, 70u})
        for (uint dimension : {0u, 3u}) cases.push_back({type, requested, index, dimension});
  const double alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / double(cases.size() * 3));
  for (const UniformityCase& c : cases) {
    std::array<double, 3> p = uniformity_p_values(make(c.type, c.requested), c.index, c.dimension);
    std::string what = std::string(sampler_name(c.type)) + " n " + std::to_string(c.requested) +
                       " index " + std::to_string(c.index) + " dim " + std::to_string(c.dimension);
    EXPECT_GT(p[0], alpha) << what << ": 1D";
    EXPECT_GT(p[1], alpha) << what << ": 2D";
    EXPECT_GT(p[2], alpha) << what << ": two consecutive 1D draws";
  }
}

// The test has power: without jitter the points sit at strata centers, which 100 (1D) and
// 20 x 20 (2D) bins tell apart from uniform for 16 strata.
TEST(Uniformity, CatchesPointsAtStrataCenters) {
  std::array<double, 3> p = uniformity_p_values(make(SAMPLER_STRATIFIED, 16, false), 5, 0);
  EXPECT_LT(p[0], 1e-6);
  EXPECT_LT(p[1], 1e-6);
  EXPECT_LT(p[2], 1e-6);
}

// RMSE of the mean of a smooth integrand over one pass of 256 samples (orthogonal: 289 =
// 17^2), over 200 pixels (independent randomizations; zsobol: 200 seeds): a stratified sampler's
// error falls faster than 1/sqrt(N), so it must be far below `independent`'s at 256 samples
// (measured ratios 0.003 to 0.09; asserted: below 0.5).
double rmse(const Sampler& s, uint n, bool two_d) {
  const uint kPixels = 200;
  // Integrands and their exact integrals over [0,1) and [0,1)^2.
  const double exact_1d = 1.0 - std::cos(1.0), exact_2d = (std::exp(1.0) - 1.0) * 0.5;
  double sum_sq = 0.0;
  for (uint k = 0; k < kPixels; ++k) {
    const uint pixel = randomized_by_seed(s) ? 4711u : k, seed = randomized_by_seed(s) ? k : 3u;
    double mean = 0.0;
    for (uint i = 0; i < n; ++i) {
      if (two_d) {
        vec2 p = draw_2d(s, pixel, i, seed, 2u);
        mean += std::exp(double(p.x)) * double(p.y);
      } else {
        mean += std::sin(double(draw_1d(s, pixel, i, seed, 2u)));
      }
    }
    mean /= n;
    double e = mean - (two_d ? exact_2d : exact_1d);
    sum_sq += e * e;
  }
  return std::sqrt(sum_sq / kPixels);
}

TEST(Convergence, FasterThanIndependent) {
  for (bool two_d : {false, true}) {
    // independent's record has no passes (sample_count 1): its 256 samples are named here.
    double independent = rmse(make(SAMPLER_INDEPENDENT, 256), 256, two_d);
    for (uint type : kStratifiedTypes) {
      const Sampler s = make(type, 256);
      double r = rmse(s, s.sample_count, two_d);
      EXPECT_LT(r, 0.5 * independent)
          << "type " << type << (two_d ? " 2D" : " 1D") << " RMSE " << r << " vs " << independent;
      std::printf("type %u %s: RMSE %.3g, independent %.3g\n", type, two_d ? "2D" : "1D", r,
                  independent);
    }
  }
}

}  // namespace
}  // namespace tr
