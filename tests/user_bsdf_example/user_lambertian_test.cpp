// A user's own Lambertian BSDF, validated with twinray::validation exactly as a user would:
// through the public header and target only, with the user's own vector math and sampling.
#include <gtest/gtest.h>
#include <twinray_validation.h>

#include <cmath>
#include <iostream>

namespace {

namespace tv = twinray::validation;

constexpr float kPi = 3.14159265358979f;

// --- The user's code under test ---------------------------------------------------------------
struct Lambertian {
  float albedo[3];

  // f(wi, wo) |cos θo| for wi, wo on the front side (+z), zero elsewhere.
  glm::vec3 eval(const glm::vec3& wi, const glm::vec3& wo) const {
    if (wi.z <= 0.0f || wo.z <= 0.0f) return glm::vec3(0.0f);
    return glm::vec3(albedo[0], albedo[1], albedo[2]) * (wo.z / kPi);
  }
  float pdf(const glm::vec3& wi, const glm::vec3& wo) const {
    return wi.z > 0.0f && wo.z > 0.0f ? wo.z / kPi : 0.0f;
  }
  // Cosine-weighted hemisphere by lifting a uniform disk point (r = √u1, φ = 2π u2) — Malley's
  // method.
  tv::BsdfSample sample(const glm::vec3& wi, const glm::vec2& u) const {
    tv::BsdfSample s;
    if (wi.z <= 0.0f) return s;  // failed draw: pdf 0, weight 0
    float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    s.wo = glm::vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x)));
    s.pdf = pdf(wi, s.wo);
    if (s.pdf <= 0.0f) return tv::BsdfSample{};
    s.weight = eval(wi, s.wo) / s.pdf;
    return s;
  }
};

// --- Wiring it to the validation library ----------------------------------------------------
tv::BsdfUnderTest under_test(const Lambertian& bsdf) {
  tv::BsdfUnderTest b;
  b.name = "user lambertian";
  b.sample = [bsdf](const glm::vec3& wi, float, const glm::vec2& u2) {
    return bsdf.sample(wi, u2);
  };
  b.pdf = [bsdf](const glm::vec3& wi, const glm::vec3& wo) { return bsdf.pdf(wi, wo); };
  b.eval = [bsdf](const glm::vec3& wi, const glm::vec3& wo) { return bsdf.eval(wi, wo); };
  b.eval_includes_cosine = true;  // eval returns f |cos θo|
  return b;
}

TEST(UserBsdf, LambertianPassesEveryCheck) {
  tv::ValidationOptions options;  // 1M draws per chi-square test, 1% overall significance
  std::vector<glm::vec3> incident = {tv::direction_from_angles(0.0, 0.0),
                                     tv::direction_from_angles(45.0, 30.0),
                                     tv::direction_from_angles(89.9, 0.0)};
  tv::Report report =
      tv::validate_bsdf(under_test(Lambertian{{0.2f, 0.5f, 0.9f}}), incident, options);
  report.print(std::cout);
  EXPECT_TRUE(report.passed());
}

TEST(UserBsdf, AnAlbedoAboveOneIsCaught) {
  tv::ValidationOptions options;
  options.chi_square.sample_count = 100000;
  tv::Report report = tv::validate_bsdf(under_test(Lambertian{{1.05f, 0.5f, 0.5f}}),
                                        {tv::direction_from_angles(30.0, 0.0)}, options);
  report.print(std::cout);
  EXPECT_FALSE(report.passed());
}

// A user's light sampler (a uniform cone towards a spherical light, cos θmax = 0.8) checked on
// the sphere with the same machinery.
TEST(UserBsdf, DirectionSamplerOfAnEmitter) {
  const float cos_max = 0.8f;
  tv::DirectionSampler light;
  light.name = "user cone light";
  light.pdf = [cos_max](const glm::vec3& w) {
    return w.z >= cos_max ? 1.0f / (2.0f * kPi * (1.0f - cos_max)) : 0.0f;
  };
  light.sample = [cos_max, pdf = light.pdf](const glm::vec2& u) {
    float cos_theta = 1.0f - u.x * (1.0f - cos_max);
    float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    float phi = 2.0f * kPi * u.y;
    glm::vec3 w(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
    return tv::DirectionSample{w, pdf(w)};
  };
  tv::ChiSquareOptions options;
  tv::ChiSquareResult result = tv::chi_square_directions(light, options);
  tv::Report report;
  report.checks.push_back(tv::report_line(light.name, glm::vec3(0.0f), result, 0.01));
  report.print(std::cout);
  EXPECT_TRUE(report.passed());
}

}  // namespace
