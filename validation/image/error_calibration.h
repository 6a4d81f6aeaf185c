// Whether a render's own error estimate is honest: N renders of one scene with distinct seeds,
// each with its variance output (per sample, or the estimate from independent randomizations,
// render/error_estimate.h), against the error the N renders show among themselves.
//   estimated: the mean over renders, pixels and channels of v / (n (r^2 + 0.01)), the expected
//              relMSE each render claims (v its variance output, n its spp);
//   observed:  the mean over pixels and channels of s^2 / (r^2 + 0.01), s^2 the sample variance
//              of the N values of the pixel: the same expectation measured over seeds, unbiased
//              for unbiased renders whatever the sampler, and free of the reference's own error
//              (r, the reference, only weights the pixels as relMSE does, metrics.h).
// The standard error of `observed` treats the pixels as independent.
#pragma once

#include <vector>

#include "validation/image/rgb_image.h"

namespace tr {

struct ErrorCalibration {
  double estimated = 0.0;
  double observed = 0.0;
  double observed_stderr = 0.0;
};

// Throws ImageError when the images differ in size or there are fewer than two renders.
ErrorCalibration error_calibration(const std::vector<RgbImage>& means,
                                   const std::vector<RgbImage>& variances, double spp,
                                   const RgbImage& reference);

}  // namespace tr
