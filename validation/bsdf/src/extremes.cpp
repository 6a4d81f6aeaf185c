// Extreme arguments: no sample(), pdf() or eval() result may be NaN, infinite or negative.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "random.h"
#include "twinray_validation.h"

namespace twinray::validation {
namespace {

glm::vec3 at_cos_theta(double cos_theta, double phi) {
  double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return glm::vec3(float(sin_theta * std::cos(phi)), float(sin_theta * std::sin(phi)),
                   float(cos_theta));
}

const double kCosines[] = {1.0, 0.5, 1e-2, 1e-4, 1e-6, 0.0, -1e-6, -0.5, -1.0};
const double kAzimuths[] = {0.3, 2.0};  // radians; away from the axes, and across them

class Inspector {
 public:
  Inspector(const BsdfUnderTest& bsdf, ExtremesResult& r) : bsdf_(bsdf), r_(r) {}

  void value(float v, const char* what, const glm::vec3& wi, const glm::vec3& wo) {
    ++r_.evaluations;
    if (std::isfinite(v) && v >= 0.0f) return;
    if (r_.failures++ == 0) {
      std::ostringstream s;
      s.precision(9);
      s << what << " = " << v << " at wi=(" << wi.x << ", " << wi.y << ", " << wi.z << ") wo=("
        << wo.x << ", " << wo.y << ", " << wo.z << ")";
      r_.first_failure = s.str();
    }
  }

  void direction(const glm::vec3& wo, const glm::vec3& wi) {
    ++r_.evaluations;
    if (std::isfinite(wo.x) && std::isfinite(wo.y) && std::isfinite(wo.z)) return;
    if (r_.failures++ == 0) {
      std::ostringstream s;
      s << "non-finite sampled direction at wi=(" << wi.x << ", " << wi.y << ", " << wi.z << ")";
      r_.first_failure = s.str();
    }
  }

  void pair(const glm::vec3& wi, const glm::vec3& wo) {
    value(bsdf_.pdf(wi, wo), "pdf", wi, wo);
    if (!bsdf_.eval) return;
    glm::vec3 e = bsdf_.eval(wi, wo);
    value(e.x, "eval.r", wi, wo);
    value(e.y, "eval.g", wi, wo);
    value(e.z, "eval.b", wi, wo);
  }

  void draw(const glm::vec3& wi, float u1, glm::vec2 u2) {
    BsdfSample s = bsdf_.sample(wi, u1, u2);
    value(s.pdf, "sampled pdf", wi, s.wo);
    value(s.weight.x, "weight.r", wi, s.wo);
    value(s.weight.y, "weight.g", wi, s.wo);
    value(s.weight.z, "weight.b", wi, s.wo);
    if (!(s.pdf > 0.0f)) return;
    direction(s.wo, wi);
    if (!s.delta) pair(wi, s.wo);
  }

 private:
  const BsdfUnderTest& bsdf_;
  ExtremesResult& r_;
};

}  // namespace

std::vector<glm::vec3> extreme_incident_directions() {
  std::vector<glm::vec3> directions;
  for (double c : kCosines) {
    for (double phi : kAzimuths) directions.push_back(at_cos_theta(c, phi));
  }
  return directions;
}

ExtremesResult extremes_check(const BsdfUnderTest& bsdf, const std::vector<glm::vec3>& incident,
                              std::size_t random_draws, std::uint64_t seed) {
  if (!bsdf.sample || !bsdf.pdf)
    throw std::invalid_argument(bsdf.name + ": sample and pdf required");
  const float one_minus = 1.0f - 0x1.0p-24f;
  const float corners[] = {0.0f, 0.5f, one_minus};
  std::vector<glm::vec3> outgoing = extreme_incident_directions();
  ExtremesResult r;
  Inspector inspect(bsdf, r);
  detail::Random random(seed);
  for (const glm::vec3& wi : incident) {
    for (float u1 : corners) {
      for (float a : corners) {
        for (float b : corners) inspect.draw(wi, u1, {a, b});
      }
    }
    for (std::size_t n = 0; n < random_draws; ++n) {
      float u1 = random.uniform();
      inspect.draw(wi, u1, random.uniform2());
    }
    for (const glm::vec3& wo : outgoing) inspect.pair(wi, wo);
    inspect.pair(wi, glm::vec3(-wi.x, -wi.y, wi.z));  // mirror
    inspect.pair(wi, -wi);                            // straight through
    inspect.pair(wi, wi);
  }
  return r;
}

}  // namespace twinray::validation
