// White-furnace tests (issue 2): inside a constant emitter of radiance 1 and with unbounded
// depth, a sphere that neither absorbs nor emits is invisible — every pixel's expected value
// is 1 — and a convex diffuse sphere of albedo rho shows exactly rho (each scattered ray
// escapes to the environment). Significance: the image mean must lie within 3 standard
// errors (two-sided, 0.27% false-failure rate), and every pixel within the normal quantile
// of a Šidák-corrected 1% test over all pixels. Radiance is computed in float32, so a path
// that always returns the same value can sit a few ulps off with zero variance: each
// standard error is combined with a float32 resolution of 1e-6 relative (about 16 ulps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render_fixture.h"

namespace tr::test {
namespace {

// Two-sided normal quantile z with P(|Z| > z) = alpha, by bisection on erfc.
double normal_two_sided_quantile(double alpha) {
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

constexpr double kFloatResolution = 1e-6;

void expect_furnace_value(const std::string& file, double expected) {
  RenderResult r = render_file(test_scene(file));
  const size_t pixels = size_t(r.width) * r.height;
  ASSERT_GT(pixels, 0u);
  EXPECT_EQ(r.stats.rejected_nonfinite, 0u);
  const double z_pixel = normal_two_sided_quantile(1.0 - std::pow(0.99, 1.0 / double(pixels * 3)));
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0, var_sum = 0.0, worst_z = 0.0, worst_mean = 0.0, worst_se = 0.0;
    for (size_t p = 0; p < pixels; ++p) {
      double mean = r.mean[p * 3 + c];
      double var = r.variance[p * 3 + c] / r.spp;
      sum += mean;
      var_sum += var;
      double se = std::sqrt(var + kFloatResolution * kFloatResolution * expected * expected);
      double z = se > 0.0 ? std::abs(mean - expected) / se : (mean == expected ? 0.0 : INFINITY);
      if (z > worst_z) {
        worst_z = z;
        worst_mean = mean;
        worst_se = se;
      }
    }
    double image_mean = sum / double(pixels);
    double image_se = std::sqrt(var_sum) / double(pixels);
    EXPECT_LE(std::abs(image_mean - expected), 3.0 * image_se)
        << file << " channel " << c << ": image mean " << image_mean << ", expected " << expected
        << " +- 3 x " << image_se;
    EXPECT_LE(worst_z, z_pixel) << file << " channel " << c << ": a pixel is " << worst_z
                                << " standard errors from " << expected << " (mean " << worst_mean
                                << ", standard error " << worst_se << ")";
  }
}

TEST(Furnace, WhiteDiffuseSphereVanishes) {
  expect_furnace_value("furnace_diffuse_white.xml", 1.0);
}
TEST(Furnace, SmoothDielectricSphereVanishes) {
  expect_furnace_value("furnace_dielectric.xml", 1.0);
}
TEST(Furnace, PerfectConductorSphereVanishes) {
  expect_furnace_value("furnace_conductor.xml", 1.0);
}
TEST(Furnace, DiffuseSphereShowsItsAlbedo) {
  expect_furnace_value("furnace_diffuse_half.xml", 0.5);
}

}  // namespace
}  // namespace tr::test
