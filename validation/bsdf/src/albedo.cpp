// Directional albedo ρ(wi) = ∫ f(wi, wo) |cos θo| dωo = E[weight] by Monte Carlo with the
// BSDF's own sampling routine (failed draws count as weight 0), and a one-sided z-test of
// energy conservation ρ ≤ 1.
#include <cmath>
#include <glm/glm.hpp>
#include <stdexcept>

#include "random.h"
#include "twinray_validation.h"

namespace twinray::validation {

AlbedoResult albedo_test(const BsdfUnderTest& bsdf, const glm::vec3& wi, std::size_t samples,
                         std::uint64_t seed) {
  if (!bsdf.sample) throw std::invalid_argument(bsdf.name + ": sample required");
  if (samples < 2) throw std::invalid_argument("albedo_test: need at least 2 samples");
  // Welford's running mean and sum of squared deviations (Chan, Golub & LeVeque 1979).
  glm::dvec3 mean(0.0), m2(0.0);
  detail::Random random(seed);
  for (std::size_t n = 1; n <= samples; ++n) {
    float u1 = random.uniform();
    BsdfSample s = bsdf.sample(wi, u1, random.uniform2());
    glm::dvec3 w = s.pdf > 0.0f ? glm::dvec3(s.weight) : glm::dvec3(0.0);
    glm::dvec3 delta = w - mean;
    mean += delta / double(n);
    m2 += delta * (w - mean);
  }
  AlbedoResult r;
  r.albedo = mean;
  r.standard_error = glm::sqrt(m2 / double(samples - 1) / double(samples));
  // H0: ρ_c ≤ 1 + 1e-5. Under H0 the CLT gives P(mean ≥ observed) ≤ 1 - Φ(z) with
  // z = (mean - 1 - 1e-5) / SE; Φ through erfc: 1 - Φ(z) = erfc(z / √2) / 2.
  const double bound = 1.0 + 1e-5;
  double p_min = 1.0;
  for (int c = 0; c < 3; ++c) {
    double p;
    if (!std::isfinite(mean[c])) {
      p = 0.0;
    } else if (r.standard_error[c] == 0.0) {
      p = mean[c] > bound ? 0.0 : 1.0;
    } else {
      p = 0.5 * std::erfc((mean[c] - bound) / r.standard_error[c] / std::sqrt(2.0));
    }
    p_min = std::min(p_min, p);
  }
  r.p_value = std::min(1.0, 3.0 * p_min);
  return r;
}

}  // namespace twinray::validation
