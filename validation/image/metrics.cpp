#include "validation/image/metrics.h"

#include <cmath>
#include <limits>

namespace tr {

ErrorMetrics error_metrics(const RgbImage& test, const RgbImage& reference) {
  check_same_size(reference, "reference", test, "test image");
  double sum_sq = 0.0, sum_rel_sq = 0.0, sum_rel_abs = 0.0;
  for (size_t i = 0; i < test.rgb.size(); ++i) {
    double a = test.rgb[i], b = reference.rgb[i], d = a - b;
    sum_sq += d * d;
    sum_rel_sq += d * d / (b * b + kRelMseEpsilon);
    sum_rel_abs += std::fabs(d) / (std::fabs(b) + kMapeEpsilon);
  }
  const double n = double(test.rgb.size());
  ErrorMetrics m;
  m.mse = sum_sq / n;
  m.rmse = std::sqrt(m.mse);
  m.relmse = sum_rel_sq / n;
  m.mape = sum_rel_abs / n;
  m.psnr = m.mse > 0.0 ? -10.0 * std::log10(m.mse) : std::numeric_limits<double>::infinity();
  return m;
}

}  // namespace tr
