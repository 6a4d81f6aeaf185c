// Checks a render whose every pixel has the same expected value in every channel, shared by
// the CPU and GPU tests. Significance: the image mean must lie within 3 standard errors
// (two-sided, 0.27% false failures), and every pixel within the normal quantile of a
// Šidák-corrected 1% test over all pixels and channels, as tests/cpu/furnace_test.cpp. A
// standard error is combined with a float32 resolution of 1e-6 relative for the pixels whose
// every sample scores the same.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/render.h"

namespace tr::test {

// Two-sided normal quantile z with P(|Z| > z) = alpha, by bisection on erfc.
inline double constant_normal_two_sided_quantile(double alpha) {
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

inline void expect_constant_image(const RenderResult& r, double expected, const std::string& what) {
  const size_t pixels = size_t(r.width) * r.height;
  ASSERT_GT(pixels, 0u);
  EXPECT_EQ(r.stats.rejected_nonfinite, 0u) << what;
  const double resolution = 1e-6 * expected;
  const double z_pixel =
      constant_normal_two_sided_quantile(1.0 - std::pow(0.99, 1.0 / double(pixels * 3)));
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0, var_sum = 0.0, worst_z = 0.0, worst_mean = 0.0;
    for (size_t p = 0; p < pixels; ++p) {
      double mean = r.mean[p * 3 + c];
      double var = r.variance[p * 3 + c] / r.spp;
      sum += mean;
      var_sum += var;
      double se = std::sqrt(var + resolution * resolution);
      double z = se > 0.0 ? std::abs(mean - expected) / se : (mean == expected ? 0.0 : INFINITY);
      if (z > worst_z) {
        worst_z = z;
        worst_mean = mean;
      }
    }
    double image_mean = sum / double(pixels);
    double image_se =
        std::sqrt(var_sum + resolution * resolution * double(pixels)) / double(pixels);
    EXPECT_LE(std::abs(image_mean - expected), 3.0 * image_se)
        << what << " channel " << c << ": image mean " << image_mean << ", expected " << expected
        << " +- 3 x " << image_se;
    EXPECT_LE(worst_z, z_pixel) << what << " channel " << c << ": a pixel is " << worst_z
                                << " standard errors from " << expected << " (mean " << worst_mean
                                << ")";
  }
}

}  // namespace tr::test
