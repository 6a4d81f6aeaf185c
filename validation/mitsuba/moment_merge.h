// Merging the passes of a Mitsuba 3 reference rendered in independent passes.
//
// Each pass is an EXR written by Mitsuba's hdrfilm for a scene whose integrator is wrapped in
// Mitsuba's `moment` integrator (src/integrators/moment.cpp, v3.8.0): besides the film's own
// colour channels it holds, per nested integrator NAME, the pixel mean of the samples' CIE XYZ
// values in channels NAME.X/Y/Z and the pixel mean of their squares in m2_NAME.X/Y/Z, and for
// each AOV channel A the nested integrator writes (Mitsuba's `aov` integrator: alb.R, dd.T, ...)
// the pixel means NAME.A and m2_NAME.A of its samples.
//
// Mitsuba's film sums a pixel's samples in float32, so one long pass drifts (about 1e-3
// relative at 32000 spp) and its variance m2 - mean^2 cancels badly. With P equal-spp passes,
//   mean = (1/P) sum_k mean_k,   var = (1/P) sum_k m2_k - mean^2,
// evaluated in double, is the mean and the (1/N-normalised) per-sample variance of all N
// samples, which is also what Chan, Golub and LeVeque's pairwise update ("Algorithms for
// computing the sample variance", The American Statistician 37(3), 1983) yields for equal-size
// groups. Its only error is that of each pass's float32 sums (at 256 spp about 1e-6 relative).
//
// The outputs follow Mitsuba's reference layout (src/render/tests/test_renders.py,
// render_ref_images): the XYZ mean and the XYZ variance, each converted to linear sRGB with
// Bitmap's XYZ -> RGB weights (src/core/bitmap.cpp), so the variance file is the XYZ variance
// mapped by that matrix, as the acceptance tests (validation/image/variance_tests.h) expect.
// AOV channels follow R, G, B under their own names (A), mean and variance as they are: an AOV
// is not a colour Mitsuba converts.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/image.h"

namespace tr {

// The channel indices of one nested integrator's moments in a pass image.
struct MomentChannels {
  std::string name;  // NAME of NAME.X (no '.' in it: the AOVs' NAME.pos.X are not colours)
  int mean[3];       // NAME.X, NAME.Y, NAME.Z
  int m2[3];         // m2_NAME.X, m2_NAME.Y, m2_NAME.Z
  std::vector<std::string> aov_names;  // A of each NAME.A with an m2_NAME.A, in channel order
  std::vector<int> aov_mean, aov_m2;   // NAME.A, m2_NAME.A
};

// The moment channels of `img`; throws ImageError("what: ...") unless exactly one nested
// integrator's six colour channels are present.
MomentChannels find_moment_channels(const Image& img, const std::string& what);

struct MergedPasses {
  Image mean;      // linear sRGB, channels R, G, B, then the AOVs
  Image variance;  // per-sample variance, Mitsuba's layout (see above)
  // XYZ and AOV values whose variance came out below zero (cancellation of float32 pass sums where
  // the true variance is about 0) and were set to 0, and the most negative such value. (The
  // RGB-mapped variance itself may be negative: the XYZ -> RGB matrix has negative weights.)
  std::size_t clamped_variances = 0;
  double most_negative_variance = 0.0;
};

// Merges equal-spp passes; `names` label the passes in error messages. Throws ImageError when
// the passes differ in size or AOVs or a value is not finite.
MergedPasses merge_moment_passes(const std::vector<Image>& passes,
                                 const std::vector<std::string>& names);

}  // namespace tr
