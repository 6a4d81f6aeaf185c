#include "quadrature.h"

#include <cmath>

namespace twinray::validation::detail {
namespace {

// QUADPACK qk15: Kronrod abscissae (xgk, descending, the last is 0), their weights (wgk), and
// the 7-point Gauss weights (wg) of the odd-indexed abscissae xgk[1], xgk[3], xgk[5], xgk[7].
const double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                        0.207784955007898467600689403773245, 0.0};
const double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
const double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                       0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

Quadrature kronrod_panel(const std::function<double(double)>& f, double a, double b) {
  double center = 0.5 * (a + b), half = 0.5 * (b - a);
  double f_center = f(center);
  double kronrod = kWgk[7] * f_center, gauss = kWg[3] * f_center;
  for (int i = 0; i < 7; ++i) {
    double pair = f(center - half * kXgk[i]) + f(center + half * kXgk[i]);
    kronrod += kWgk[i] * pair;
    if (i % 2 == 1) gauss += kWg[i / 2] * pair;
  }
  return {kronrod * half, std::abs(kronrod - gauss) * half};
}

void refine(const std::function<double(double)>& f, double a, double b, double tolerance, int depth,
            const QuadratureSettings& s, Quadrature& total) {
  if (depth >= s.min_depth) {
    Quadrature q = kronrod_panel(f, a, b);
    if (q.error <= tolerance || depth >= s.max_depth) {
      total.value += q.value;
      total.error += q.error;
      return;
    }
  }
  double m = 0.5 * (a + b);
  refine(f, a, m, 0.5 * tolerance, depth + 1, s, total);
  refine(f, m, b, 0.5 * tolerance, depth + 1, s, total);
}

}  // namespace

Quadrature adaptive_gauss_kronrod(const std::function<double(double)>& f, double a, double b,
                                  const QuadratureSettings& settings) {
  Quadrature total;
  refine(f, a, b, settings.tolerance, 0, settings, total);
  return total;
}

Quadrature adaptive_gauss_kronrod_2d(const std::function<double(double, double)>& f, double x0,
                                     double x1, double y0, double y1,
                                     const QuadratureSettings& settings) {
  QuadratureSettings inner = settings;
  inner.tolerance = settings.tolerance / (2.0 * (x1 - x0));
  double inner_error = 0.0;
  auto line = [&](double x) {
    Quadrature q = adaptive_gauss_kronrod([&](double y) { return f(x, y); }, y0, y1, inner);
    inner_error = std::max(inner_error, q.error);
    return q.value;
  };
  QuadratureSettings outer = settings;
  outer.tolerance = 0.5 * settings.tolerance;
  Quadrature q = adaptive_gauss_kronrod(line, x0, x1, outer);
  // The outer weights are positive and sum to (x1 - x0): the inner errors contribute at most
  // that width times the largest of them.
  q.error += (x1 - x0) * inner_error;
  return q;
}

}  // namespace twinray::validation::detail
