#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "twinray_validation.h"

namespace twinray::validation {
namespace {

constexpr int kMaxIterations = 100000;
constexpr double kRelativeEpsilon = 1e-15;

// Lower series, Abramowitz & Stegun 6.5.29 / Numerical Recipes 3rd ed. eq. 6.2.5:
//   P(a, x) = e^{-x} x^a Σ_{n≥0} x^n / (a (a+1) ... (a+n)),  used for x < a + 1.
double gamma_p_series(double a, double x) {
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * kRelativeEpsilon) {
      return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
    }
  }
  throw std::runtime_error("regularized_gamma_q: series did not converge for a=" +
                           std::to_string(a) + ", x=" + std::to_string(x));
}

// Continued fraction, Abramowitz & Stegun 6.5.31 in the even form of Numerical Recipes 3rd ed.
// eq. 6.2.7, Q(a, x) = e^{-x} x^a / Γ(a) · 1/(x+1-a- 1(1-a)/(x+3-a- 2(2-a)/(x+5-a- ...))),
// evaluated with the modified Lentz method (NR §5.2), used for x ≥ a + 1.
double gamma_q_continued_fraction(double a, double x) {
  const double tiny = std::numeric_limits<double>::min() / kRelativeEpsilon;
  double b = x + 1.0 - a;
  double c = 1.0 / tiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kRelativeEpsilon) {
      return h * std::exp(-x + a * std::log(x) - std::lgamma(a));
    }
  }
  throw std::runtime_error("regularized_gamma_q: continued fraction did not converge for a=" +
                           std::to_string(a) + ", x=" + std::to_string(x));
}

}  // namespace

double regularized_gamma_q(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) {
    throw std::invalid_argument("regularized_gamma_q: need a > 0 and x >= 0, got a=" +
                                std::to_string(a) + ", x=" + std::to_string(x));
  }
  if (x == 0.0) return 1.0;
  if (x < a + 1.0) return 1.0 - gamma_p_series(a, x);
  return gamma_q_continued_fraction(a, x);
}

// The chi-square distribution with k degrees of freedom is Γ(k/2, 2): its survival function
// is Q(k/2, X²/2) (Abramowitz & Stegun 26.4.19).
double chi_square_p_value(double statistic, int dof) {
  if (dof < 1) throw std::invalid_argument("chi_square_p_value: dof must be >= 1");
  return regularized_gamma_q(0.5 * dof, 0.5 * std::max(statistic, 0.0));
}

// Šidák, "Rectangular Confidence Regions for the Means of Multivariate Normal Distributions",
// JASA 1967: n independent tests at level α_n = 1 - (1 - α)^(1/n) reject any with probability α.
double sidak_alpha(double overall, std::size_t tests) {
  if (!(overall > 0.0 && overall < 1.0) || tests == 0) {
    throw std::invalid_argument("sidak_alpha: need 0 < overall < 1 and tests > 0");
  }
  return -std::expm1(std::log1p(-overall) / double(tests));
}

}  // namespace twinray::validation
