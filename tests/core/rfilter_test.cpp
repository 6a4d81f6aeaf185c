// The reconstruction filters of core/rfilter.h against the formulas of Mitsuba's
// src/rfilters/*.cpp, evaluated independently in double, and their integrals (midpoint rule
// with 2e5 steps; quadrature error below 1e-8 for these piecewise-smooth functions).
#include "core/rfilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace tr {
namespace {

double integral(const std::function<double(double)>& f, double radius) {
  const int steps = 200000;
  double sum = 0.0, h = 2.0 * radius / steps;
  for (int i = 0; i < steps; ++i) sum += f(-radius + (i + 0.5) * h);
  return sum * h;
}

double mitchell(double x, double b, double c) {
  x = std::abs(x);
  if (x >= 2) return 0;
  if (x < 1)
    return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + 6 - 2 * b) / 6;
  return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + 8 * b +
          24 * c) /
         6;
}

double lanczos(double x, double a) {
  x = std::abs(x);
  if (x == 0) return 1;
  if (x > a) return 0;
  return std::sin(M_PI * x) * std::sin(M_PI * x / a) / (M_PI * x * M_PI * x / a);
}

TEST(ReconstructionFilter, TentIsTheTriangleOfItsRadius) {
  for (float r : {0.7f, 1.0f, 2.5f}) {
    for (float x = -3.0f; x <= 3.0f; x += 0.0625f)
      EXPECT_NEAR(rfilter_tent(x, r), std::max(0.0, 1.0 - std::abs(x) / r), 1e-6) << x;
    EXPECT_NEAR(integral([&](double x) { return rfilter_tent(float(x), r); }, r), r, 1e-6);
  }
}

// Mitchell & Netravali's cubics integrate to 1 for every B, C (their eq. 8 normalization).
TEST(ReconstructionFilter, MitchellFamilyMatchesTheCubicsAndIntegratesToOne) {
  const float bc[][2] = {{1.0f / 3, 1.0f / 3}, {0.2f, 0.4f}, {0.0f, 0.5f}, {1.0f, 0.0f}};
  for (auto& p : bc) {
    for (float x = -2.5f; x <= 2.5f; x += 0.03125f)
      EXPECT_NEAR(rfilter_mitchell(x, p[0], p[1]), mitchell(x, p[0], p[1]), 1e-6) << x;
    EXPECT_NEAR(integral([&](double x) { return rfilter_mitchell(float(x), p[0], p[1]); }, 2.0),
                1.0, 1e-6);
  }
  // f(0) = (6 - 2B) / 6 and f(1) = B / 6.
  EXPECT_NEAR(rfilter_mitchell(0.0f, 0.2f, 0.4f), (6 - 0.4) / 6, 1e-7);
  EXPECT_NEAR(rfilter_mitchell(1.0f, 0.2f, 0.4f), 0.2 / 6, 1e-7);
  // Catmull-Rom is the member B = 0, C = 1/2.
  vec4 none(0.0f);
  for (float x = -2.0f; x <= 2.0f; x += 0.1f)
    EXPECT_EQ(rfilter_eval(RFILTER_CATMULLROM, none, x), rfilter_mitchell(x, 0.0f, 0.5f));
}

TEST(ReconstructionFilter, LanczosIsTheWindowedSinc) {
  for (float a : {1.0f, 2.0f, 3.0f}) {
    for (float x = -a - 0.5f; x <= a + 0.5f; x += 0.0371f)
      EXPECT_NEAR(rfilter_lanczos(x, a), lanczos(x, a), 3e-7) << a << " " << x;
    EXPECT_EQ(rfilter_lanczos(0.0f, a), 1.0f);
    EXPECT_NEAR(integral([&](double x) { return rfilter_lanczos(float(x), a); }, a),
                integral([&](double x) { return lanczos(x, a); }, a), 1e-6);
  }
}

// gaussian.cpp: the fit P(t), t = x^2 / sigma^2, minus P(16), clamped at 0, evaluated here in
// double. In float (Mitsuba's and ours) the alternating terms of P cancel to within ~3e-5 near
// the radius. The fit itself approximates exp(-t / 2) - exp(-8) within 5e-4.
TEST(ReconstructionFilter, GaussianIsMitsubasRemezFit) {
  const double coeff[10] = {9.992604880e-1, -4.977025247e-1, 1.222248550e-1, -1.932406282e-2,
                            2.136713061e-3, -1.679873860e-4, 9.202145248e-6, -3.329417433e-7,
                            7.128382794e-9, -6.821193280e-11};
  auto fit = [&](double t) {
    double p = 0.0;
    for (int i = 9; i >= 0; --i) p = p * t + coeff[i];
    return p;
  };
  for (float sigma : {0.25f, 0.5f, 1.3f}) {
    const double r = 4.0 * sigma;
    auto exact = [&](double x) {
      return std::max(0.0, std::exp(-x * x / (2 * sigma * sigma)) - std::exp(-8.0));
    };
    for (double x = -r - 0.5; x <= r + 0.5; x += r / 97) {
      const float xf = float(x);
      const double t = double(xf) * xf / (double(sigma) * sigma);
      const double expected = std::max(0.0, fit(t) - fit(16.0));
      EXPECT_NEAR(rfilter_gaussian(xf, sigma), expected, 3e-5) << sigma << " " << x;
      EXPECT_NEAR(rfilter_gaussian(xf, sigma), exact(x), 5e-4) << sigma << " " << x;
    }
    EXPECT_NEAR(rfilter_gaussian(float(r), sigma), 0.0f, 3e-5f);
  }
}

// init_discretization: entry i holds f(r i / 31), the last one 0.
TEST(ReconstructionFilter, TableSamplesTheFilterAtMultiplesOfRadiusOver31) {
  vec4 params(0.2f, 0.4f, 0.0f, 0.0f);
  for (uint i = 0; i < FILTER_RESOLUTION; ++i)
    EXPECT_EQ(rfilter_table_entry(RFILTER_MITCHELL, params, 2.0f, i),
              rfilter_mitchell(2.0f * float(i) / 31.0f, 0.2f, 0.4f));
  EXPECT_EQ(rfilter_table_entry(RFILTER_MITCHELL, params, 2.0f, FILTER_RESOLUTION), 0.0f);
  EXPECT_EQ(rfilter_table_entry(RFILTER_TENT, vec4(1.5f), 1.5f, 0u), 1.0f);
}

}  // namespace
}  // namespace tr
