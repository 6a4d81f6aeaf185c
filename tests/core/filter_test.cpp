// The gaussian reconstruction filter's sampling (core/camera.h) must estimate the normalized
// filter: E[w] = 1 and E[w x^2] = ∫ f x^2 / ∫ f, for Mitsuba's shifted gaussian f. Checked by
// Monte Carlo with the counter-based RNG over 2^20 samples, within 5 standard errors
// (two-sided false-failure probability 6e-7), and the quadrature of f by the midpoint rule.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera.h"
#include "core/rng.h"

namespace tr {
namespace {

double shifted_gaussian(double x, double sigma, double r) {
  return std::max(0.0,
                  std::exp(-x * x / (2 * sigma * sigma)) - std::exp(-r * r / (2 * sigma * sigma)));
}

TEST(GaussianFilter, SamplingEstimatesTheNormalizedFilter) {
  const float sigma = 0.5f, r = 2.0f;
  double f_int = 0, f_x2 = 0;
  const int steps = 200000;
  for (int i = 0; i < steps; ++i) {
    double x = -r + (i + 0.5) * (2.0 * r / steps);
    f_int += shifted_gaussian(x, sigma, r);
    f_x2 += shifted_gaussian(x, sigma, r) * x * x;
  }
  const double expected_x2 = f_x2 / f_int;
  const int n = 1 << 20;
  double sw = 0, sw2 = 0, swx2 = 0, swx2_2 = 0;
  for (int i = 0; i < n; ++i) {
    Rng rng = rng_init(uint(i), 0u, 1u);
    float w;
    float x = sample_gaussian_filter_1d(rng_next_1d(rng), sigma, r, w);
    ASSERT_GE(w, 0.0f);
    ASSERT_LE(std::abs(x), r);
    sw += w;
    sw2 += double(w) * w;
    swx2 += double(w) * x * x;
    swx2_2 += double(w) * x * x * double(w) * x * x;
  }
  double mean_w = sw / n, se_w = std::sqrt((sw2 / n - mean_w * mean_w) / n);
  double mean_wx2 = swx2 / n, se_wx2 = std::sqrt((swx2_2 / n - mean_wx2 * mean_wx2) / n);
  EXPECT_NEAR(mean_w, 1.0, 5 * se_w + 1e-5);
  EXPECT_NEAR(mean_wx2, expected_x2, 5 * se_wx2 + 1e-5);
}

TEST(GaussianFilter, ErfinvInvertsErf) {
  for (float x = -0.999f; x < 1.0f; x += 0.0123f)
    EXPECT_NEAR(erf_approx(erfinv_approx(x)), x, 2e-6f) << x;
}

}  // namespace
}  // namespace tr

namespace tr {
namespace {

TEST(PortableTrig, MatchesTheLibraryWithinFourUlpScaledError) {
  for (int i = -2000; i <= 2000; ++i) {
    float x = i * 0.0004995f;
    EXPECT_NEAR(acos_portable(x), std::acos(double(x)), 4e-7 + 2e-7 * std::acos(double(x))) << x;
    for (int j = 0; j < 8; ++j) {
      float y = std::sin(j * 0.785398f + 0.1f), z = std::cos(j * 0.785398f + 0.1f) * (i * 0.001f);
      EXPECT_NEAR(atan2_portable(y, z), std::atan2(double(y), double(z)), 5e-7) << y << " " << z;
    }
  }
}

}  // namespace
}  // namespace tr

namespace tr {
namespace {

// Mitsuba's perspective camera unprojects (film sample + principal_point_offset): with an
// offset of +0.25 along x, the film centre looks where the film point 0.75 would, i.e. at
// camera-space x/z = (1 - 2 * 0.75) tan(fov_x / 2).
TEST(Camera, PrincipalPointOffsetShiftsTheFilmSample) {
  Camera c{};
  c.to_world[0] = vec4(1, 0, 0, 0);
  c.to_world[1] = vec4(0, 1, 0, 0);
  c.to_world[2] = vec4(0, 0, 1, 0);
  c.type = SENSOR_PERSPECTIVE;
  c.width = 2;
  c.height = 2;
  c.tan_half_fov = vec2(1.0f, 1.0f);
  c.principal_point = vec2(0.25f, 0.0f);
  c.near_clip = 1e-2f;
  c.far_clip = 1e4f;
  Ray r = camera_ray(c, vec2(1.0f, 1.0f), vec2(0.5f));
  EXPECT_NEAR(r.d.x / r.d.z, -0.5f, 1e-6f);
  EXPECT_NEAR(r.d.y / r.d.z, 0.0f, 1e-6f);
}

}  // namespace
}  // namespace tr
