// Comparison of a test image A with a reference image B: error metrics, SSIM, LDR-FLIP, the
// variance-based hypothesis tests and lockstep agreement, with a pass/fail verdict.
//
// Which checks decide the verdict:
//  - B is a converged reference (A has no variance image): pixel_z and block_z
//    (shared/mitsuba-tests/README.md tests 1 and 2) and gain_z (a matched-filter test for a
//    global gain, see variance_tests.h) when B's per-sample variance and both sample counts are
//    known (pixel_z alone without B's count);
//  - two noisy renders (both variance images): pixel_welch and block_welch when both sample
//    counts are known;
//  - lockstep agreement when CompareOptions::lockstep is set (otherwise it is only reported);
//  - max_relmse / max_flip when given.
// With none of these the report has no criteria and `passed` is true.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "validation/image/flip.h"
#include "validation/image/lockstep.h"
#include "validation/image/metrics.h"
#include "validation/image/rgb_image.h"
#include "validation/image/ssim.h"
#include "validation/image/variance_tests.h"

namespace tr {

struct CompareInputs {
  std::string test_name = "A", reference_name = "B";
  RgbImage test, reference;
  // Per-sample variance images (Mitsuba `moment` semantics) and samples per pixel; 0 = unknown.
  std::optional<RgbImage> test_variance, reference_variance;
  double test_spp = 0.0, reference_spp = 0.0;
  // The lockstep check's rounding control: B's renderer on the same scene with its camera moved
  // by one float ulp (validation/image/lockstep.h).
  std::optional<RgbImage> rounding_control;
};

struct CompareOptions {
  VarianceTestOptions variance;
  bool lockstep = false;
  LockstepOptions lockstep_options;
  double pixels_per_degree = flip_default_pixels_per_degree();
  std::optional<double> max_relmse, max_flip;
};

struct CompareReport {
  std::string test_name, reference_name;
  int width = 0, height = 0;
  ErrorMetrics metrics;
  std::optional<SsimResult> ssim;
  FlipResult flip;
  double pixels_per_degree = 0.0;
  std::optional<HypothesisTestResult> pixel_z, block_z, gain_z, pixel_welch, block_welch;
  LockstepResult lockstep;
  bool lockstep_decides = false;
  std::vector<std::string> criteria;  // checks that decide the verdict
  std::vector<std::string> failures;  // one line per failed check
  std::vector<std::string> notes;     // checks that could not run, and why
  bool passed = false;

  std::vector<const std::optional<HypothesisTestResult>*> tests() const {
    return {&pixel_z, &block_z, &gain_z, &pixel_welch, &block_welch};
  }
};

// Throws ImageError when the inputs differ in size.
CompareReport compare_images(const CompareInputs& inputs, const CompareOptions& options = {});

// The report as a JSON object (see the field names in compare.cpp).
std::string compare_report_json(const CompareReport& report, const CompareOptions& options);

enum class HeatmapMetric {
  flip,            // the FLIP map on [0, 1]
  relative_error,  // mean over channels of |a - b| / (|b| + kMapeEpsilon), on [0, range]
  z,               // max over channels of |z| (pixel_z, else pixel_welch's |t|), on [0, z at alpha]
};

// Per-pixel values of `metric` and the value range the heatmap spans. Throws
// std::invalid_argument for `z` when no per-pixel hypothesis test ran.
std::vector<float> heatmap_values(const CompareReport& report, const CompareInputs& inputs,
                                  HeatmapMetric metric, double relative_range, float* lo,
                                  float* hi);

}  // namespace tr
