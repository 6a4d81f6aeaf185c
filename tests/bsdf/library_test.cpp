// Unit tests of twinray::validation's own machinery against known values.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "src/quadrature.h"
#include "twinray_validation.h"

namespace tv = twinray::validation;

TEST(ValidationLibrary, RegularizedGammaQKnownValues) {
  for (double x : {0.0, 0.1, 1.0, 2.5, 10.0, 40.0}) {
    EXPECT_NEAR(tv::regularized_gamma_q(1.0, x), std::exp(-x), 1e-13);             // Q(1,x) = e^-x
    EXPECT_NEAR(tv::regularized_gamma_q(0.5, x), std::erfc(std::sqrt(x)), 1e-13);  // A&S 6.5.17
  }
  // Q(2, x) = (1 + x) e^-x (A&S 6.5.13).
  EXPECT_NEAR(tv::regularized_gamma_q(2.0, 3.0), 4.0 * std::exp(-3.0), 1e-13);
}

TEST(ValidationLibrary, ChiSquareQuantiles) {
  // 95% quantiles of the chi-square distribution (NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
  EXPECT_NEAR(tv::chi_square_p_value(3.841, 1), 0.05, 1e-4);
  EXPECT_NEAR(tv::chi_square_p_value(18.307, 10), 0.05, 1e-4);
  EXPECT_NEAR(tv::chi_square_p_value(124.342, 100), 0.05, 1e-4);
  // Median of chi-square with many degrees of freedom is about k (1 - 2/(9k))^3.
  double k = 800.0;
  EXPECT_NEAR(tv::chi_square_p_value(k * std::pow(1.0 - 2.0 / (9.0 * k), 3.0), 800), 0.5, 2e-3);
}

TEST(ValidationLibrary, Sidak) {
  EXPECT_NEAR(tv::sidak_alpha(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(1.0 - std::pow(1.0 - tv::sidak_alpha(0.01, 500), 500.0), 0.01, 1e-12);
}

namespace {

tv::DirectionSampler uniform_sphere(float claimed_density) {
  tv::DirectionSampler s;
  s.name = "uniform sphere";
  s.sample = [claimed_density](const glm::vec2& u) {
    float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 6.2831853f * u.y;
    return tv::DirectionSample{glm::vec3(r * std::cos(phi), r * std::sin(phi), z), claimed_density};
  };
  s.pdf = [claimed_density](const glm::vec3&) { return claimed_density; };
  return s;
}

tv::ChiSquareOptions small() {
  tv::ChiSquareOptions o;
  o.sample_count = 100000;
  o.integration_tolerance = 1e-7;
  return o;
}

}  // namespace

TEST(ValidationLibrary, ChiSquareAcceptsCorrectAndRejectsWrongDensity) {
  const float inv_four_pi = 0.0795774715f;
  tv::ChiSquareResult good = tv::chi_square_directions(uniform_sphere(inv_four_pi), small());
  EXPECT_TRUE(good.failure.empty()) << good.failure;
  EXPECT_GT(good.p_value, 1e-4);
  EXPECT_NEAR(good.pdf_integral, 1.0, 1e-5);
  EXPECT_EQ(good.dof, 199);
  tv::ChiSquareResult bad = tv::chi_square_directions(uniform_sphere(0.9f * inv_four_pi), small());
  EXPECT_LT(bad.p_value, 1e-10);
}

TEST(ValidationLibrary, ChiSquareReportsDrawsOutsideTheSupport) {
  tv::PlanarSampler s;
  s.name = "square sampled, left half claimed";
  s.sample = [](const glm::vec2& u) { return u; };
  s.pdf = [](const glm::vec2& p) { return p.x < 0.5f ? 2.0f : 0.0f; };
  tv::ChiSquareResult r = tv::chi_square_planar(s, small());
  EXPECT_FALSE(r.failure.empty());
  EXPECT_EQ(r.p_value, 0.0);
  EXPECT_GT(r.outside_support, 0u);
}

TEST(ValidationLibrary, DeltaAtomsAreTestedAgainstTheirProbabilities) {
  // A mirror/pass-through pair chosen with probabilities 0.3 / 0.7; the reported probability is
  // either right or swapped.
  for (bool swapped : {false, true}) {
    tv::BsdfUnderTest b;
    b.name = "two atoms";
    b.pdf = [](const glm::vec3&, const glm::vec3&) { return 0.0f; };
    b.sample = [swapped](const glm::vec3& wi, float u1, const glm::vec2&) {
      tv::BsdfSample s;
      s.delta = true;
      s.weight = glm::vec3(1.0f);
      bool mirror = u1 < 0.3f;
      s.wo = mirror ? glm::vec3(-wi.x, -wi.y, wi.z) : -wi;
      s.pdf = (mirror != swapped) ? 0.3f : 0.7f;
      return s;
    };
    tv::ChiSquareResult r =
        tv::chi_square_bsdf(b, glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f)), small());
    EXPECT_EQ(r.delta_atoms, 2u);
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-6);
    if (swapped) {
      EXPECT_LT(r.p_value, 1e-10);
    } else {
      EXPECT_GT(r.p_value, 1e-4);
    }
  }
}

TEST(ValidationLibrary, ConsistencyFindsWeightAndPdfMismatches) {
  tv::BsdfUnderTest b;
  b.name = "lambert with a wrong weight";
  b.pdf = [](const glm::vec3&, const glm::vec3& wo) {
    return wo.z > 0.0f ? wo.z / 3.14159265f : 0.0f;
  };
  b.eval = [](const glm::vec3&, const glm::vec3& wo) {
    return glm::vec3(wo.z > 0.0f ? 0.5f * wo.z / 3.14159265f : 0.0f);
  };
  b.sample = [](const glm::vec3&, float, const glm::vec2& u) {
    float r = std::sqrt(u.x), phi = 6.2831853f * u.y;
    tv::BsdfSample s;
    s.wo = glm::vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x)));
    s.pdf = s.wo.z / 3.14159265f * 1.01f;  // 1% off
    s.weight = glm::vec3(0.6f);            // should be 0.5
    return s;
  };
  tv::ConsistencyOptions o;
  o.sample_count = 1000;
  o.random_pairs = 1000;
  tv::ConsistencyResult r = tv::consistency_check(b, glm::vec3(0.0f, 0.0f, 1.0f), o);
  EXPECT_FALSE(r.passed());
  EXPECT_GT(r.pdf_mismatch, 900u);
  EXPECT_GT(r.weight_mismatch, 900u);
  EXPECT_EQ(r.eval_without_pdf, 0u);
  EXPECT_EQ(r.not_reciprocal, 0u);
}

TEST(ValidationLibrary, DensityIntegralBeyondOneFails) {
  const float inv_four_pi = 0.0795774715f;
  tv::DirectionSampler s = uniform_sphere(inv_four_pi);
  s.pdf = [inv_four_pi](const glm::vec3& w) {
    return w.z > 0.0f ? 1.001f * inv_four_pi : inv_four_pi;
  };
  tv::ChiSquareResult r = tv::chi_square_directions(s, small());
  EXPECT_NE(r.failure.find("pdf integrates to"), std::string::npos) << r.failure;
}

TEST(ValidationLibrary, GaussKronrodIntegratesKnownFunctions) {
  using namespace twinray::validation::detail;
  QuadratureSettings s{1e-12, 1000};
  // K15 is exact for polynomials of degree 22 (Kronrod 1965).
  Quadrature q = adaptive_gauss_kronrod([](double x) { return std::pow(x, 20.0); }, {0.0, 1.0}, s);
  EXPECT_NEAR(q.value, 1.0 / 21.0, 1e-15);
  q = adaptive_gauss_kronrod([](double x) { return std::exp(-x * x); }, {-3.0, 3.0}, s);
  EXPECT_NEAR(q.value, std::sqrt(3.14159265358979323846) * std::erf(3.0), 1e-12);
  // A step at x = 1/3 inside the interval: the error bound must cover the actual error.
  QuadratureSettings coarse{1e-6, 64};
  q = adaptive_gauss_kronrod([](double x) { return x < 1.0 / 3.0 ? 1.0 : 0.0; }, {0.0, 1.0},
                             coarse);
  EXPECT_LE(std::abs(q.value - 1.0 / 3.0), q.error);
  Quadrature q2 = adaptive_gauss_kronrod_2d([](double x, double y) { return x * y * y; },
                                            {0.0, 1.0}, {0.0, 2.0}, s);
  EXPECT_NEAR(q2.value, 0.5 * 8.0 / 3.0, 1e-12);
}

TEST(ValidationLibrary, DeltaLobesWithTheSameDirectionAreToldApartByLabel) {
  // A mask-like pass-through (probability 0.4) and a refraction straight through (0.6) at
  // normal incidence: one direction, two lobes, each reporting its own probability.
  auto sampler = [](unsigned second_label) {
    tv::BsdfUnderTest b;
    b.name = "pass-through + refraction";
    b.pdf = [](const glm::vec3&, const glm::vec3&) { return 0.0f; };
    b.sample = [second_label](const glm::vec3& wi, float u1, const glm::vec2&) {
      tv::BsdfSample s;
      s.delta = true;
      s.weight = glm::vec3(1.0f);
      s.wo = -wi;
      bool pass = u1 < 0.4f;
      s.pdf = pass ? 0.4f : 0.6f;
      s.lobe = pass ? 1u : second_label;
      return s;
    };
    return b;
  };
  const glm::vec3 normal(0.0f, 0.0f, 1.0f);
  tv::ConsistencyOptions o;
  o.sample_count = 1000;
  tv::ChiSquareResult labelled = tv::chi_square_bsdf(sampler(2u), normal, small());
  EXPECT_EQ(labelled.delta_atoms, 2u);
  EXPECT_GT(labelled.p_value, 1e-4);
  EXPECT_TRUE(tv::consistency_check(sampler(2u), normal, o).passed());
  EXPECT_GT(tv::consistency_check(sampler(1u), normal, o).delta_mismatch, 0u);
}
