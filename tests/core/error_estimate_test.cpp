// The pass moments of render/film_moments.h and the variance output of render/error_estimate.h:
// pass values are the passes' own develop() values (also with negative samples), and the
// variance is S times their sample variance from 2 completed passes on, the per-sample variance
// before and for samplers without passes.
#include "render/error_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "render/film_error.h"
#include "render/film_state.h"

namespace tr {
namespace {

struct Sample {
  double L[3];
  bool negative;
};

// The CPU backend's order (cpu_backend/render_cpu.cpp): each sample into its group and the pass
// in progress, the pass ended after every pass_size samples.
FilmMoments accumulate(const std::vector<Sample>& samples, std::uint32_t pass_size) {
  FilmMoments m;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    add_sample(s.negative ? m.negative : m.positive, s.L);
    add_to_pass(m.passes, s.negative ? -1.0 : 1.0, 1.0, s.L);
    if ((i + 1) % pass_size == 0) end_pass(m.passes);
  }
  return m;
}

std::vector<Sample> draw(std::size_t n, double negative_fraction, unsigned seed) {
  std::mt19937 gen(seed);
  std::lognormal_distribution<double> radiance(0.0, 1.0);
  std::bernoulli_distribution negative(negative_fraction);
  std::vector<Sample> samples(n);
  for (Sample& s : samples) {
    const double x = radiance(gen);
    s = {{x, 2.0 * x, 0.5}, negative(gen)};
  }
  return samples;
}

// develop() of the samples [first, first + count) alone.
void develop_range(const std::vector<Sample>& samples, std::size_t first, std::size_t count,
                   double value[3]) {
  FilmMoments m;
  for (std::size_t i = first; i < first + count; ++i)
    add_sample(samples[i].negative ? m.negative : m.positive, samples[i].L);
  double variance[3];
  develop(m, value, variance);
}

void expect_passes_of(const std::vector<Sample>& samples, std::uint32_t s) {
  const FilmMoments m = accumulate(samples, s);
  const std::size_t k = samples.size() / s;
  ASSERT_EQ(m.passes.values.n, double(k));
  std::vector<double> values[3];
  for (std::size_t p = 0; p < k; ++p) {
    double v[3];
    develop_range(samples, p * s, s, v);
    for (int c = 0; c < 3; ++c) values[c].push_back(v[c]);
  }
  double mean[3], variance[3];
  develop_estimate(m, s, mean, variance);
  double per_sample_mean[3], per_sample[3];
  develop(m, per_sample_mean, per_sample);
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (double v : values[c]) sum += v;
    const double pass_mean = sum / double(k);
    double squares = 0.0;
    for (double v : values[c]) squares += (v - pass_mean) * (v - pass_mean);
    EXPECT_NEAR(m.passes.values.mean[c], pass_mean, 1e-12 * (1.0 + std::abs(pass_mean))) << c;
    EXPECT_NEAR(variance[c], double(s) * squares / double(k - 1),
                1e-9 * (1.0 + double(s) * squares / double(k - 1)))
        << c;
    EXPECT_EQ(mean[c], per_sample_mean[c]) << "the value is develop()'s";
  }
}

TEST(PassMoments, PassValuesAndTheirVarianceWithoutNegativeSamples) {
  expect_passes_of(draw(16 * 9, 0.0, 1), 16);
}

TEST(PassMoments, NegativeSamplesGiveEachPassItsRatioEstimate) {
  const std::vector<Sample> samples = draw(8 * 12, 0.2, 2);
  expect_passes_of(samples, 8);
  // The first pass's value by hand: sum(s L) / sum(s).
  const FilmMoments one = accumulate(std::vector<Sample>(samples.begin(), samples.begin() + 8), 8);
  double sum = 0.0, signs = 0.0;
  for (int i = 0; i < 8; ++i) {
    const double s = samples[i].negative ? -1.0 : 1.0;
    sum += s * samples[i].L[0];
    signs += s;
  }
  ASSERT_NE(signs, 0.0);
  EXPECT_NEAR(one.passes.values.mean[0], sum / signs, 1e-12 * std::abs(sum / signs));
}

TEST(PassMoments, ThePassInProgressIsKeptApart) {
  const std::vector<Sample> samples = draw(16 * 2 + 5, 0.1, 3);
  const FilmMoments m = accumulate(samples, 16);
  EXPECT_EQ(m.passes.values.n, 2.0);
  double signs = 0.0, sum = 0.0;
  for (std::size_t i = 32; i < samples.size(); ++i) {
    signs += samples[i].negative ? -1.0 : 1.0;
    sum += (samples[i].negative ? -1.0 : 1.0) * samples[i].L[1];
  }
  EXPECT_EQ(m.passes.signs, signs);
  EXPECT_NEAR(m.passes.sum[1], sum, 1e-12 * std::abs(sum));
}

TEST(ErrorEstimate, PerSampleBelowTwoPassesAndWithoutPasses) {
  const std::vector<Sample> samples = draw(16 + 15, 0.0, 4);
  const FilmMoments m = accumulate(samples, 16);  // one pass and part of a second
  double mean[3], variance[3], per_sample_mean[3], per_sample[3];
  develop(m, per_sample_mean, per_sample);
  develop_estimate(m, 16, mean, variance);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(variance[c], per_sample[c]);
  const FilmMoments many = accumulate(draw(16 * 4, 0.0, 5), 16);
  develop(many, per_sample_mean, per_sample);
  develop_estimate(many, 0, mean, variance);  // independent: no passes
  for (int c = 0; c < 3; ++c) EXPECT_EQ(variance[c], per_sample[c]);
}

TEST(ErrorEstimate, NamesWhatTheVarianceIs) {
  EXPECT_EQ(variance_estimate_name(0, 1024), "per-sample");
  EXPECT_EQ(variance_estimate_name(64, 64), "per-sample");
  EXPECT_EQ(variance_estimate_name(64, 127), "per-sample");
  EXPECT_EQ(variance_estimate_name(64, 128), "randomizations: 2 passes of 64 samples");
  EXPECT_EQ(variance_estimate_name(16, 16 * 16 + 3), "randomizations: 16 passes of 16 samples");
}

// render/film_state.h: a film's accumulators keep the negative groups from the first one that
// has negative samples on, the pass moments only with passes, and read absent parts as zeros;
// the positive count is the sample count less the negative one.
TEST(FilmMomentArray, HoldsOnlyThePartsItIsGiven) {
  FilmMomentArray without_passes(3, false);
  EXPECT_FALSE(without_passes.has_passes());
  EXPECT_FALSE(without_passes.has_negative());
  const FilmMoments positive = accumulate(draw(8, 0.0, 8), 4);
  without_passes.set(1, positive);
  EXPECT_FALSE(without_passes.has_negative());
  EXPECT_EQ(without_passes.at(1, 8).positive.n, 8.0);
  EXPECT_EQ(without_passes.at(1, 8).passes.values.n, 0.0);  // dropped: nothing reads them

  FilmMomentArray with_passes(3, true);
  const FilmMoments signed_samples = accumulate(draw(64, 0.5, 9), 4);
  ASSERT_GT(signed_samples.negative.n, 0.0);
  with_passes.set(2, signed_samples);
  EXPECT_TRUE(with_passes.has_negative());
  const FilmMoments back = with_passes.at(2, 64);
  EXPECT_EQ(std::memcmp(&back, &signed_samples, sizeof back), 0);
  EXPECT_EQ(with_passes.at(0, 64).negative.n, 0.0);
  EXPECT_EQ(with_passes.at(0, 64).positive.n, 64.0);
}

// render --target-error trusts a correlated sampler's estimate from kMinErrorPasses passes on.
TEST(ErrorEstimate, RelativeErrorNeedsSixteenPasses) {
  FilmState film = empty_film(1, 1, 0, 4);
  film.pixels.set(0, accumulate(draw(4 * 15, 0.0, 6), 4));
  film.samples = 4 * 15;
  EXPECT_TRUE(std::isinf(estimated_relative_error(film)));
  film.pixels.set(0, accumulate(draw(4 * 16, 0.0, 6), 4));
  film.samples = 4 * 16;
  EXPECT_TRUE(std::isfinite(estimated_relative_error(film)));
  FilmState independent = empty_film(1, 1);
  independent.pixels.set(0, accumulate(draw(16, 0.0, 7), 16));
  independent.samples = 16;
  EXPECT_TRUE(std::isfinite(estimated_relative_error(independent)));
}

}  // namespace
}  // namespace tr
