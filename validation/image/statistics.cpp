#include "validation/image/statistics.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tr {

double normal_two_sided_p(double z) { return std::erfc(std::fabs(z) / std::sqrt(2.0)); }

double normal_two_sided_quantile(double p) {
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 100; ++i) {
    double mid = 0.5 * (lo + hi);
    (normal_two_sided_p(mid) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {

// Continued fraction for I_x(a, b) (DLMF 8.17.22), modified Lentz evaluation.
double beta_continued_fraction(double x, double a, double b) {
  const double tiny = 1e-300, eps = 1e-15;
  const int max_iterations = 100000;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= max_iterations; ++m) {
    // Even step: d_{2m} = m (b - m) x / ((a + 2m - 1)(a + 2m)).
    double aa = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    // Odd step: d_{2m+1} = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)).
    aa = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < eps) return h;
  }
  throw std::runtime_error(
      "incomplete beta continued fraction did not converge for x=" + std::to_string(x) +
      " a=" + std::to_string(a) + " b=" + std::to_string(b));
}

}  // namespace

double regularized_incomplete_beta(double x, double a, double b) {
  if (!(a > 0.0 && b > 0.0) || !(x >= 0.0 && x <= 1.0))
    throw std::invalid_argument("regularized_incomplete_beta: bad arguments");
  if (x == 0.0 || x == 1.0) return x;
  double log_front =
      a * std::log(x) + b * std::log1p(-x) + std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b);
  // The fraction converges quickly for x < (a + 1) / (a + b + 2); otherwise use the symmetry
  // I_x(a, b) = 1 - I_{1-x}(b, a) (DLMF 8.17.4).
  if (x < (a + 1.0) / (a + b + 2.0))
    return std::exp(log_front) * beta_continued_fraction(x, a, b) / a;
  return 1.0 - std::exp(log_front) * beta_continued_fraction(1.0 - x, b, a) / b;
}

double student_two_sided_p(double t, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("student_two_sided_p: dof must be positive");
  if (std::isinf(t)) return 0.0;
  if (std::isinf(dof)) return normal_two_sided_p(t);
  return regularized_incomplete_beta(dof / (dof + t * t), 0.5 * dof, 0.5);
}

double sidak_alpha(double family_alpha, double tests) {
  return -std::expm1(std::log1p(-family_alpha) / tests);
}

}  // namespace tr
