// Scalar error metrics of a test image against a reference, over all pixels and RGB channels
// of the linear images (no clamping, no tone mapping).
#pragma once

#include "validation/image/rgb_image.h"

namespace tr {

// Denominator offsets of the relative metrics.
constexpr double kRelMseEpsilon = 1e-2;
constexpr double kMapeEpsilon = 1e-2;

struct ErrorMetrics {
  double mse = 0.0;     // mean (a - b)^2
  double rmse = 0.0;    // sqrt(mse)
  double relmse = 0.0;  // mean (a - b)^2 / (b^2 + kRelMseEpsilon)  (Rousselle et al. 2011)
  double mape = 0.0;    // mean |a - b| / (|b| + kMapeEpsilon)
  double psnr = 0.0;    // 10 log10(1 / mse) dB: peak value 1 on the linear scale; +inf if mse=0
};

ErrorMetrics error_metrics(const RgbImage& test, const RgbImage& reference);

}  // namespace tr
