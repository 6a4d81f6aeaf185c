// Adaptive Gauss-Kronrod quadrature in one and two dimensions. Each panel is integrated by the
// 15-point Kronrod rule and its embedded 7-point Gauss rule (Kronrod 1965; nodes and weights of
// QUADPACK's qk15, Piessens et al. 1983); |K15 - G7| is the panel's error estimate, which is
// pessimistic for smooth integrands. Panels are bisected until the estimate meets the tolerance
// (halved with each bisection) or the maximum depth is reached; a minimum depth forces the
// first bisections so that narrow peaks between the nodes are not missed. The rules never
// evaluate a panel's endpoints, so a density that jumps at a bin edge (the horizon) is
// integrated from inside the bin only.
#ifndef TWINRAY_VALIDATION_QUADRATURE_H
#define TWINRAY_VALIDATION_QUADRATURE_H

#include <functional>

namespace twinray::validation::detail {

struct QuadratureSettings {
  double tolerance;  // absolute
  int min_depth;
  int max_depth;
};

struct Quadrature {
  double value = 0.0;
  double error = 0.0;  // sum of the accepted panels' |K15 - G7|
};

Quadrature adaptive_gauss_kronrod(const std::function<double(double)>& f, double a, double b,
                                  const QuadratureSettings& settings);

// ∫_{x0}^{x1} ∫_{y0}^{y1} f(x, y) dy dx, nested: the outer rule integrates inner adaptive
// integrals, each to tolerance / (2 (x1 - x0)), the outer one to tolerance / 2.
Quadrature adaptive_gauss_kronrod_2d(const std::function<double(double, double)>& f, double x0,
                                     double x1, double y0, double y1,
                                     const QuadratureSettings& settings);

}  // namespace twinray::validation::detail

#endif
