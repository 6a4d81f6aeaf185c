// Deterministic agreement between a BSDF's sample(), pdf() and eval() at one incident direction.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "random.h"
#include "twinray_validation.h"

namespace twinray::validation {
namespace {

bool close(double a, double b, const ConsistencyOptions& o) {
  return std::abs(a - b) <=
         o.relative_tolerance * std::max(std::abs(a), std::abs(b)) + o.absolute_tolerance;
}

bool close3(const glm::dvec3& a, const glm::dvec3& b, const ConsistencyOptions& o) {
  return close(a.x, b.x, o) && close(a.y, b.y, o) && close(a.z, b.z, o);
}

std::string str(const glm::dvec3& v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

glm::vec3 uniform_sphere(glm::vec2 u) {
  // pbrt-v4 §A.5.2: z = 1 - 2 u0, φ = 2π u1.
  float z = 1.0f - 2.0f * u.x;
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  float phi = 6.2831853f * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

class Checker {
 public:
  Checker(const BsdfUnderTest& bsdf, const glm::vec3& wi, const ConsistencyOptions& o,
          ConsistencyResult& r)
      : bsdf_(bsdf), wi_(wi), o_(o), r_(r) {}

  // eval with the |cos θo| factor, whatever the user's convention.
  glm::dvec3 eval_cos(const glm::vec3& wi, const glm::vec3& wo) const {
    glm::dvec3 e(bsdf_.eval(wi, wo));
    return bsdf_.eval_includes_cosine ? e : e * std::abs(double(wo.z));
  }

  void fail(std::size_t& counter, const std::string& what, const glm::vec3& wo) {
    if (counter++ == 0 && r_.first_failure.empty()) {
      std::ostringstream s;
      s.precision(9);
      s << what << " at wi=" << str(glm::dvec3(wi_)) << " wo=" << str(glm::dvec3(wo));
      r_.first_failure = s.str();
    }
  }

  // eval > 0 ⇒ pdf > 0, and f(wi, wo)|cos θi||cos θo| symmetric for same-side pairs.
  void check_pair(const glm::vec3& wo, double pdf) {
    glm::dvec3 e = eval_cos(wi_, wo);
    if ((e.x > 0.0 || e.y > 0.0 || e.z > 0.0) && !(pdf > 0.0)) {
      fail(r_.eval_without_pdf, "eval " + str(e) + " > 0 with pdf " + std::to_string(pdf), wo);
    }
    if (bsdf_.reciprocal && double(wi_.z) * double(wo.z) > 0.0) {
      glm::dvec3 forward = e * std::abs(double(wi_.z));
      glm::dvec3 backward = eval_cos(wo, wi_) * std::abs(double(wo.z));
      if (!close3(forward, backward, o_)) {
        fail(r_.not_reciprocal,
             "f(wi,wo)|cos i||cos o| = " + str(forward) + " but reversed " + str(backward), wo);
      }
    }
  }

  void check_sample(float u1, glm::vec2 u2) {
    BsdfSample s = bsdf_.sample(wi_, u1, u2);
    ++r_.checked_samples;
    if (!(s.pdf > 0.0f)) {
      if (s.weight != glm::vec3(0.0f)) {
        fail(r_.failed_with_weight,
             "failed draw (pdf " + std::to_string(s.pdf) + ") with weight " +
                 str(glm::dvec3(s.weight)),
             s.wo);
      }
      return;
    }
    if (!(std::abs(glm::length(glm::dvec3(s.wo)) - 1.0) <= 1e-3)) {
      fail(r_.not_unit,
           "sampled direction of length " + std::to_string(glm::length(glm::dvec3(s.wo))), s.wo);
    }
    if (s.delta) {
      auto key = std::make_tuple(s.lobe, std::lround(s.wo.x * 1e4), std::lround(s.wo.y * 1e4),
                                 std::lround(s.wo.z * 1e4));
      auto [it, inserted] = atoms_.try_emplace(key, double(s.pdf));
      if (!close(it->second, s.pdf, o_)) {
        fail(r_.delta_mismatch,
             "delta direction reported with probability " + std::to_string(s.pdf) + " and " +
                 std::to_string(it->second),
             s.wo);
      }
      return;
    }
    double pdf = bsdf_.pdf(wi_, s.wo);
    if (!close(pdf, s.pdf, o_)) {
      std::ostringstream m;
      m.precision(9);
      m << "pdf() = " << pdf << " but sample() reported " << s.pdf;
      fail(r_.pdf_mismatch, m.str(), s.wo);
    }
    if (!bsdf_.eval) return;
    glm::dvec3 expected_weight = eval_cos(wi_, s.wo) / double(s.pdf);
    if (!close3(glm::dvec3(s.weight), expected_weight, o_)) {
      fail(r_.weight_mismatch,
           "weight " + str(glm::dvec3(s.weight)) + " but eval|cos|/pdf = " + str(expected_weight),
           s.wo);
    }
    check_pair(s.wo, pdf);
  }

 private:
  const BsdfUnderTest& bsdf_;
  glm::vec3 wi_;
  const ConsistencyOptions& o_;
  ConsistencyResult& r_;
  std::map<std::tuple<unsigned, long, long, long>, double> atoms_;
};

}  // namespace

bool ConsistencyResult::passed() const {
  return weight_mismatch == 0 && pdf_mismatch == 0 && failed_with_weight == 0 && not_unit == 0 &&
         eval_without_pdf == 0 && not_reciprocal == 0 && delta_mismatch == 0;
}

ConsistencyResult consistency_check(const BsdfUnderTest& bsdf, const glm::vec3& wi,
                                    const ConsistencyOptions& o) {
  if (!bsdf.sample || !bsdf.pdf)
    throw std::invalid_argument(bsdf.name + ": sample and pdf required");
  ConsistencyResult r;
  Checker checker(bsdf, wi, o, r);
  detail::Random random(o.seed);
  for (std::size_t n = 0; n < o.sample_count; ++n) {
    float u1 = random.uniform();
    checker.check_sample(u1, random.uniform2());
  }
  if (bsdf.eval) {
    for (std::size_t n = 0; n < o.random_pairs; ++n) {
      glm::vec3 wo = uniform_sphere(random.uniform2());
      checker.check_pair(wo, bsdf.pdf(wi, wo));
    }
  }
  return r;
}

}  // namespace twinray::validation
