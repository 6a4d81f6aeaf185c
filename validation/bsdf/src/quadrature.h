// Globally adaptive Gauss-Kronrod quadrature in one and two dimensions, after QUADPACK's qag
// (Piessens et al. 1983): each panel is integrated by the 15-point Kronrod rule and its embedded
// 7-point Gauss rule (Kronrod 1965; nodes and weights of qk15), |K15 - G7| being the panel's
// error estimate; the panel with the largest estimate is bisected until the total estimate
// meets the tolerance or the panel budget is spent, which bounds the cost where float noise in
// the integrand keeps the estimate from converging. The rules never evaluate a panel's
// endpoints, so a density that jumps at a bin edge (the horizon) is integrated from inside the
// bin only.
#ifndef TWINRAY_VALIDATION_QUADRATURE_H
#define TWINRAY_VALIDATION_QUADRATURE_H

#include <functional>
#include <vector>

namespace twinray::validation::detail {

struct QuadratureSettings {
  double tolerance;  // absolute, on the whole integral
  int max_panels;    // per one-dimensional integral
};

struct Quadrature {
  double value = 0.0;
  double error = 0.0;  // sum of the panels' |K15 - G7|
};

// ∫ f over [breaks.front(), breaks.back()], starting from the panels between consecutive
// breakpoints (ascending; duplicates are skipped).
Quadrature adaptive_gauss_kronrod(const std::function<double(double)>& f,
                                  const std::vector<double>& breaks,
                                  const QuadratureSettings& settings);

// ∫∫ f(x, y) dy dx over [x_breaks.front(), x_breaks.back()] × [y_breaks.front(),
// y_breaks.back()], nested: the outer rule integrates inner adaptive integrals, each to
// tolerance / (2 width_x), the outer one to tolerance / 2. Breakpoints placed where the
// integrand concentrates (e.g. at quantiles of draws from it) keep a narrow peak from falling
// between the nodes of the first panels.
Quadrature adaptive_gauss_kronrod_2d(const std::function<double(double, double)>& f,
                                     const std::vector<double>& x_breaks,
                                     const std::vector<double>& y_breaks,
                                     const QuadratureSettings& settings);

}  // namespace twinray::validation::detail

#endif
