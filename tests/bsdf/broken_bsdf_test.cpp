// Deliberately broken samplers must fail the suite at the suite's own Šidák level: the proof
// that the chi-square machinery can catch the bugs it is meant to catch.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "cases.h"
#include "core/warp.h"
#include "suite_size.h"
#include "twinray_validation.h"

namespace tr::bsdf_suite {
namespace {
namespace tv = twinray::validation;

tv::ValidationOptions suite_options() { return validation_options(suite_size(), alpha_per_test()); }

const std::vector<glm::vec3> kIncident = {tv::direction_from_angles(30.0, 20.0),
                                          tv::direction_from_angles(85.0, 20.0)};

std::size_t failed_checks(const tv::Report& r, const std::string& check) {
  std::size_t n = 0;
  for (const tv::CheckResult& c : r.checks) n += (c.check == check && !c.passed) ? 1 : 0;
  return n;
}

// Lambertian reflectance 0.8 sampled with the cosine warp, but pdf() (and the sampled pdf)
// claims cos²θ / π instead of cos θ / π: off by a factor cos θ.
tv::BsdfUnderTest lambert_with_pdf_off_by_cos() {
  tv::BsdfUnderTest b;
  b.name = "broken: pdf off by cos";
  auto pdf = [](const glm::vec3& wi, const glm::vec3& wo) {
    return wi.z > 0.0f && wo.z > 0.0f ? wo.z * wo.z * INV_PI : 0.0f;
  };
  b.pdf = pdf;
  b.eval = [](const glm::vec3& wi, const glm::vec3& wo) {
    return wi.z > 0.0f && wo.z > 0.0f ? glm::vec3(0.8f * INV_PI * wo.z) : glm::vec3(0.0f);
  };
  b.sample = [pdf](const glm::vec3& wi, float, const glm::vec2& u2) {
    tv::BsdfSample s;
    if (wi.z <= 0.0f) return s;
    s.wo = square_to_cosine_hemisphere(u2);
    s.pdf = pdf(wi, s.wo);
    s.weight = s.pdf > 0.0f ? glm::vec3(0.8f * INV_PI * s.wo.z / s.pdf) : glm::vec3(0.0f);
    return s;
  };
  return b;
}

// A mixture of a diffuse lobe and a power-cosine lobe about the normal (exponent n = 20, pdf
// (n+1)/(2π) cos^n θ, the modified Phong lobe of Lafortune & Willems 1994). pdf() mixes the lobes
// 50/50; the sampler picks the glossy lobe with probability 0.6 — a wrong lobe weight.
tv::BsdfUnderTest mixture_with_wrong_lobe_weight() {
  const float n = 20.0f;
  auto glossy_pdf = [n](const glm::vec3& wo) {
    return wo.z > 0.0f ? (n + 1.0f) * INV_TWO_PI * std::pow(wo.z, n) : 0.0f;
  };
  auto pdf = [glossy_pdf](const glm::vec3& wi, const glm::vec3& wo) {
    if (wi.z <= 0.0f) return 0.0f;
    return 0.5f * square_to_cosine_hemisphere_pdf(wo) + 0.5f * glossy_pdf(wo);
  };
  tv::BsdfUnderTest b;
  b.name = "broken: lobe chosen 60/40, pdf says 50/50";
  b.reciprocal = false;  // the glossy lobe is fixed about the normal, not a physical BRDF
  b.pdf = pdf;
  b.eval = [pdf](const glm::vec3& wi, const glm::vec3& wo) {
    return glm::vec3(0.5f * pdf(wi, wo));
  };
  b.sample = [n, pdf](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    tv::BsdfSample s;
    if (wi.z <= 0.0f) return s;
    if (u1 < 0.6f) {
      // Inverse CDF of the power-cosine lobe: cos θ = u^(1/(n+1)).
      float cos_theta = std::pow(u2.x, 1.0f / (n + 1.0f));
      float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
      float phi = 2.0f * PI * u2.y;
      s.wo = glm::vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
    } else {
      s.wo = square_to_cosine_hemisphere(u2);
    }
    s.pdf = pdf(wi, s.wo);
    s.weight = s.pdf > 0.0f ? glm::vec3(0.5f) : glm::vec3(0.0f);
    return s;
  };
  return b;
}

TEST(BrokenBsdf, PdfOffByCosineFailsChiSquare) {
  tv::Report r = tv::validate_bsdf(lambert_with_pdf_off_by_cos(), kIncident, suite_options());
  r.print(std::cout);
  EXPECT_FALSE(r.passed());
  EXPECT_EQ(failed_checks(r, "chi2"), kIncident.size());
}

TEST(BrokenBsdf, WrongLobeWeightFailsChiSquare) {
  tv::Report r = tv::validate_bsdf(mixture_with_wrong_lobe_weight(), kIncident, suite_options());
  r.print(std::cout);
  EXPECT_FALSE(r.passed());
  EXPECT_EQ(failed_checks(r, "chi2"), kIncident.size());
}

// The same mixture sampled with the right weights passes: the failures above are the bugs'.
TEST(BrokenBsdf, CorrectedMixturePasses) {
  tv::BsdfUnderTest b = mixture_with_wrong_lobe_weight();
  tv::SampleFunction broken = b.sample;
  b.name = "mixture, lobe chosen 50/50";
  b.sample = [broken](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    // Maps u1 < 0.5 onto the broken sampler's glossy branch (u1 < 0.6) and the rest onto its
    // diffuse branch, so each lobe is chosen with probability 1/2.
    return broken(wi, u1 < 0.5f ? u1 * 1.2f : 0.6f + (u1 - 0.5f) * 0.8f, u2);
  };
  tv::Report r = tv::validate_bsdf(b, kIncident, suite_options());
  r.print(std::cout);
  EXPECT_TRUE(r.passed());
}

}  // namespace
}  // namespace tr::bsdf_suite
