#include "quadrature.h"

#include <algorithm>
#include <cmath>
#include <queue>

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

struct Panel {
  double a, b, value, error;
  bool operator<(const Panel& other) const { return error < other.error; }
};

Panel kronrod_panel(const std::function<double(double)>& f, double a, double b) {
  double center = 0.5 * (a + b), half = 0.5 * (b - a);
  double f_center = f(center);
  double kronrod = kWgk[7] * f_center, gauss = kWg[3] * f_center;
  for (int i = 0; i < 7; ++i) {
    double pair = f(center - half * kXgk[i]) + f(center + half * kXgk[i]);
    kronrod += kWgk[i] * pair;
    if (i % 2 == 1) gauss += kWg[i / 2] * pair;
  }
  return {a, b, kronrod * half, std::abs(kronrod - gauss) * half};
}

}  // namespace

Quadrature adaptive_gauss_kronrod(const std::function<double(double)>& f,
                                  const std::vector<double>& breaks,
                                  const QuadratureSettings& settings) {
  std::priority_queue<Panel> panels;
  double value = 0.0, error = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    if (!(breaks[i + 1] > breaks[i])) continue;
    Panel p = kronrod_panel(f, breaks[i], breaks[i + 1]);
    value += p.value;
    error += p.error;
    panels.push(p);
  }
  while (error > settings.tolerance && int(panels.size()) < settings.max_panels) {
    Panel worst = panels.top();
    panels.pop();
    double m = 0.5 * (worst.a + worst.b);
    Panel left = kronrod_panel(f, worst.a, m), right = kronrod_panel(f, m, worst.b);
    value += left.value + right.value - worst.value;
    error += left.error + right.error - worst.error;
    panels.push(left);
    panels.push(right);
  }
  // Recompute the sums: the running updates accumulate cancellation error.
  Quadrature q;
  while (!panels.empty()) {
    q.value += panels.top().value;
    q.error += panels.top().error;
    panels.pop();
  }
  return q;
}

Quadrature adaptive_gauss_kronrod_2d(const std::function<double(double, double)>& f,
                                     const std::vector<double>& x_breaks,
                                     const std::vector<double>& y_breaks,
                                     const QuadratureSettings& settings) {
  double width_x = x_breaks.back() - x_breaks.front();
  QuadratureSettings inner = settings;
  inner.tolerance = settings.tolerance / (2.0 * width_x);
  double inner_error = 0.0;
  auto line = [&](double x) {
    Quadrature q = adaptive_gauss_kronrod([&](double y) { return f(x, y); }, y_breaks, inner);
    inner_error = std::max(inner_error, q.error);
    return q.value;
  };
  QuadratureSettings outer = settings;
  outer.tolerance = 0.5 * settings.tolerance;
  Quadrature q = adaptive_gauss_kronrod(line, x_breaks, outer);
  // The outer weights are positive and sum to width_x: the inner errors contribute at most
  // that width times the largest of them.
  q.error += width_x * inner_error;
  return q;
}

}  // namespace twinray::validation::detail
