#include "validation/image/error_calibration.h"

#include <cmath>

#include "validation/image/metrics.h"

namespace tr {

ErrorCalibration error_calibration(const std::vector<RgbImage>& means,
                                   const std::vector<RgbImage>& variances, double spp,
                                   const RgbImage& reference) {
  if (means.size() < 2 || variances.size() != means.size())
    throw ImageError("error calibration: needs two or more renders, each with its variance");
  for (size_t k = 0; k < means.size(); ++k) {
    check_same_size(reference, "reference", means[k], "render");
    check_same_size(reference, "reference", variances[k], "variance");
  }
  const double renders = double(means.size()), values = double(reference.rgb.size());
  ErrorCalibration c;
  double sum_sq = 0.0;
  for (size_t i = 0; i < reference.rgb.size(); ++i) {
    const double weight = 1.0 / (reference.rgb[i] * reference.rgb[i] + kRelMseEpsilon);
    double mean = 0.0, m2 = 0.0, n = 0.0;
    for (size_t k = 0; k < means.size(); ++k) {
      c.estimated += variances[k].rgb[i] / spp * weight / (renders * values);
      n += 1.0;
      const double delta = means[k].rgb[i] - mean;
      mean += delta / n;
      m2 += delta * (means[k].rgb[i] - mean);
    }
    const double observed = m2 / (renders - 1.0) * weight;
    c.observed += observed / values;
    sum_sq += observed * observed;
  }
  c.observed_stderr =
      std::sqrt(std::fmax(0.0, sum_sq / values - c.observed * c.observed) / (values - 1.0));
  return c;
}

}  // namespace tr
