// core/microfacet.h: special functions, normalisation of D and of the visible-normal
// density, and agreement of the sampled normals with microfacet_pdf through moments.
#include "core/microfacet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tr {
namespace {

TEST(Microfacet, ErfMatchesStd) {
  // The fit's 1.2e-7 plus float rounding.
  for (float x = -4.0f; x <= 4.0f; x += 0.01f) EXPECT_NEAR(erf_approx(x), std::erf(x), 4e-7f) << x;
}

TEST(Microfacet, ErfinvInvertsErf) {
  for (float y = -0.999f; y <= 0.999f; y += 0.001f) {
    float x = erfinv_approx(y);
    EXPECT_NEAR(std::erf(double(x)), y, 2e-6 + 2e-6 * std::abs(y)) << y;
  }
}

// Integral of f(m) over the upper hemisphere with the substitution tan(theta) = a s/(1-s)
// (a ~ alpha concentrates nodes where D lives), midpoint rule in double.
template <typename F>
double integrate_hemisphere(F f, double a) {
  const int n_s = 800;
  const int n_phi = 256;
  double sum = 0.0;
  for (int i = 0; i < n_s; ++i) {
    double s = (i + 0.5) / n_s;
    double tan_t = a * s / (1.0 - s);
    double dtan_ds = a / ((1.0 - s) * (1.0 - s));
    double cos_t = 1.0 / std::sqrt(1.0 + tan_t * tan_t);
    double sin_t = tan_t * cos_t;
    double dtheta = dtan_ds * cos_t * cos_t;  // d theta = cos^2 d tan
    for (int j = 0; j < n_phi; ++j) {
      double phi = 2.0 * M_PI * (j + 0.5) / n_phi;
      vec3 m(float(sin_t * std::cos(phi)), float(sin_t * std::sin(phi)), float(cos_t));
      sum += f(m) * sin_t * dtheta;
    }
  }
  return sum * (1.0 / n_s) * (2.0 * M_PI / n_phi);
}

struct Config {
  bool beckmann;
  float alpha_u;
  float alpha_v;
};

const Config kConfigs[] = {{false, 0.02f, 0.02f}, {false, 0.1f, 0.1f}, {false, 0.5f, 0.5f},
                           {false, 1.0f, 1.0f},   {false, 0.2f, 0.6f}, {true, 0.02f, 0.02f},
                           {true, 0.1f, 0.1f},    {true, 0.5f, 0.5f},  {true, 1.0f, 1.0f},
                           {true, 0.6f, 0.2f}};

TEST(Microfacet, ProjectedAreaIsOne) {
  // \int D(m) cos(theta_m) dm = 1 (Walter et al. 2007, eq. 4).
  for (const Config& c : kConfigs) {
    Microfacet d = microfacet_make(c.beckmann, c.alpha_u, c.alpha_v, false);
    double a = std::sqrt(c.alpha_u * c.alpha_v);
    double integral = integrate_hemisphere([&](vec3 m) { return microfacet_d(d, m) * m.z; }, a);
    EXPECT_NEAR(integral, 1.0, 2e-3) << c.beckmann << " " << c.alpha_u << " " << c.alpha_v;
  }
}

TEST(Microfacet, VisibleNormalDensityIsNormalised) {
  // \int G1(wi, m) max(0, wi.m) D(m) dm = cos(theta_i) (Heitz 2014, eq. 8) with the exact
  // Smith G1 of microfacet_pdf; the tolerance is the quadrature's.
  for (const Config& c : kConfigs) {
    Microfacet d = microfacet_make(c.beckmann, c.alpha_u, c.alpha_v, true);
    for (float cos_i : {1.0f, 0.7f, 0.2f}) {
      vec3 wi(std::sqrt(1.0f - cos_i * cos_i) * 0.6f, std::sqrt(1.0f - cos_i * cos_i) * 0.8f,
              cos_i);
      double a = std::sqrt(c.alpha_u * c.alpha_v);
      double integral = integrate_hemisphere([&](vec3 m) { return microfacet_pdf(d, wi, m); }, a);
      EXPECT_NEAR(integral, 1.0, 2e-3)
          << c.beckmann << " " << c.alpha_u << " " << c.alpha_v << " cos " << cos_i;
    }
  }
}

TEST(Microfacet, SampledMomentsMatchPdf) {
  // E[m.x], E[m.y], E[m.z], E[m.x^2] of sampled normals against \int (...) pdf dm: a
  // sampler drawing from another density than microfacet_pdf fails this at 6 sigma.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (const Config& c : kConfigs) {
    for (bool visible : {false, true}) {
      Microfacet d = microfacet_make(c.beckmann, c.alpha_u, c.alpha_v, visible);
      vec3 wi = normalize(vec3(0.5f, -0.3f, 0.6f));
      const int n = 200000;
      double sum[4] = {0, 0, 0, 0};
      double sum2[4] = {0, 0, 0, 0};
      for (int i = 0; i < n; ++i) {
        vec3 m = microfacet_sample(d, wi, vec2(uni(rng), uni(rng)));
        ASSERT_TRUE(std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z));
        double g[4] = {m.x, m.y, m.z, m.x * m.x};
        for (int k = 0; k < 4; ++k) {
          sum[k] += g[k];
          sum2[k] += g[k] * g[k];
        }
      }
      double a = std::sqrt(c.alpha_u * c.alpha_v);
      auto moment = [&](int k) {
        return integrate_hemisphere(
            [&](vec3 m) {
              double g[4] = {m.x, m.y, m.z, m.x * m.x};
              return g[k] * microfacet_pdf(d, wi, m);
            },
            a);
      };
      for (int k = 0; k < 4; ++k) {
        double mean = sum[k] / n;
        double sigma = std::sqrt(std::max(sum2[k] / n - mean * mean, 1e-12) / n);
        double expected = moment(k);
        EXPECT_NEAR(mean, expected, 6.0 * sigma + 2e-4)
            << "beckmann " << c.beckmann << " visible " << visible << " alpha " << c.alpha_u << ","
            << c.alpha_v << " moment " << k;
      }
    }
  }
}

TEST(Microfacet, BeckmannRationalG1WithinItsStatedError) {
  // Walter et al.'s fit of the Beckmann G1 is within 0.35% of the exact Smith term.
  for (float alpha : {0.05f, 0.3f, 1.0f}) {
    Microfacet d = microfacet_make(true, alpha, alpha, true);
    for (float cos_v = 0.02f; cos_v <= 1.0f; cos_v += 0.02f) {
      vec3 v(std::sqrt(1.0f - cos_v * cos_v), 0.0f, cos_v);
      vec3 n(0.0f, 0.0f, 1.0f);
      float exact = microfacet_smith_g1_exact(d, v, n);
      EXPECT_NEAR(microfacet_smith_g1(d, v, n), exact, 3.5e-3f * exact + 1e-6f)
          << alpha << " " << cos_v;
    }
  }
}

TEST(Microfacet, SmithG1Limits) {
  Microfacet d = microfacet_make(false, 0.3f, 0.3f, true);
  vec3 n(0.0f, 0.0f, 1.0f);
  EXPECT_EQ(microfacet_smith_g1(d, n, n), 1.0f);
  // Back-facing microfacet.
  EXPECT_EQ(microfacet_smith_g1(d, normalize(vec3(1.0f, 0.0f, 0.1f)),
                                normalize(vec3(-1.0f, 0.0f, 0.05f))),
            0.0f);
  // GGX closed form 2 / (1 + sqrt(1 + alpha^2 tan^2)).
  vec3 v = normalize(vec3(0.8f, 0.0f, 0.6f));
  float tan2 = (0.8f * 0.8f) / (0.6f * 0.6f);
  EXPECT_NEAR(microfacet_smith_g1(d, v, n), 2.0f / (1.0f + std::sqrt(1.0f + 0.09f * tan2)), 1e-6f);
}

}  // namespace
}  // namespace tr
