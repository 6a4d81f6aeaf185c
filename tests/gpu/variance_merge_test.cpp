// Batch merging (Chan, Golub & LeVeque 1979) against a two-pass mean and variance.
#include "gpu_backend/variance_merge.h"

#include <gtest/gtest.h>

#include <random>

namespace tr {
namespace {

TEST(GpuVarianceMerge, MatchesTwoPassOverUnevenBatches) {
  std::mt19937 gen(7);
  std::lognormal_distribution<float> radiance(0.0f, 1.5f);
  const uint32_t batch_sizes[] = {1, 3, 64, 7, 256, 1, 100};
  std::vector<float> samples;
  MomentAccumulator acc(1);
  for (uint32_t n : batch_sizes) {
    PixelBatch batch{};
    for (uint32_t i = 1; i <= n; ++i) {
      // The shader's float Welford update (shaders/accumulate.glsl), green channel 2x red.
      float x = radiance(gen);
      samples.push_back(x);
      vec3 v(x, 2.0f * x, 0.0f);
      vec3 delta = v - batch.mean;
      batch.mean += delta / float(i);
      batch.m2 += delta * (v - batch.mean);
    }
    acc.merge(&batch, n);
  }
  double mean = 0.0;
  for (float x : samples) mean += x;
  mean /= samples.size();
  double m2 = 0.0;
  for (float x : samples) m2 += (x - mean) * (x - mean);
  const double variance = m2 / (samples.size() - 1);

  ASSERT_EQ(acc.count(), samples.size());
  std::vector<double> var = acc.variance();
  EXPECT_NEAR(acc.mean()[0], mean, 1e-6 * mean);
  EXPECT_NEAR(acc.mean()[1], 2.0 * mean, 2e-6 * mean);
  EXPECT_NEAR(var[0], variance, 1e-5 * variance);
  EXPECT_NEAR(var[1], 4.0 * variance, 4e-5 * variance);
  EXPECT_EQ(acc.mean()[2], 0.0);
  EXPECT_EQ(var[2], 0.0);
}

TEST(GpuVarianceMerge, SingleSampleHasZeroVariance) {
  MomentAccumulator acc(2);
  PixelBatch batch[2] = {};
  batch[0].mean = vec3(1.0f, 2.0f, 3.0f);
  acc.merge(batch, 1);
  EXPECT_EQ(acc.mean()[1], 2.0);
  for (double v : acc.variance()) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace tr
