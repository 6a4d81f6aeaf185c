// error_calibration (validation/image/error_calibration.h): renders whose variance output is the
// true per-sample variance are called honest, within the sampling error of the spread among
// them; an estimate four times too large is told apart; fewer than two renders are refused.
#include "validation/image/error_calibration.h"

#include <gtest/gtest.h>

#include <random>

namespace tr {
namespace {

RgbImage constant(double v) {
  RgbImage img;
  img.width = img.height = 64;
  img.rgb.assign(3 * img.pixel_count(), v);
  return img;
}

// 16 renders of spp samples of per-sample variance sigma^2 around the reference 0.5, each with
// the variance output `claimed`.
ErrorCalibration calibrate(double claimed) {
  const double sigma = 0.2, spp = 64.0;
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, sigma / std::sqrt(spp));
  std::vector<RgbImage> means, variances;
  for (int k = 0; k < 16; ++k) {
    RgbImage m = constant(0.5);
    for (double& v : m.rgb) v += noise(rng);
    means.push_back(m);
    variances.push_back(constant(claimed));
  }
  return error_calibration(means, variances, spp, constant(0.5));
}

TEST(ErrorCalibration, AnHonestEstimateMatchesTheSpread) {
  const double expected = 0.04 / 64.0 / (0.25 + 0.01);
  ErrorCalibration c = calibrate(0.04);
  EXPECT_NEAR(c.estimated, expected, 1e-12 * expected);
  // 12288 values, each s^2 with 15 degrees of freedom: the mean within 4 standard errors.
  EXPECT_NEAR(c.observed, expected, 4.0 * c.observed_stderr);
  EXPECT_NEAR(c.observed_stderr, expected * std::sqrt(2.0 / 15.0 / 12288.0),
              0.1 * c.observed_stderr);
}

TEST(ErrorCalibration, AnEstimateFourTimesTooLargeIsToldApart) {
  ErrorCalibration c = calibrate(0.16);
  EXPECT_GT(c.estimated / c.observed, 3.5);
}

TEST(ErrorCalibration, NeedsTwoRenders) {
  EXPECT_THROW(error_calibration({constant(0.5)}, {constant(0.1)}, 4.0, constant(0.5)), ImageError);
}

}  // namespace
}  // namespace tr
