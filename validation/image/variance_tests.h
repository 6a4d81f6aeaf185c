// Hypothesis tests of a Monte Carlo render against a reference whose per-sample variance is
// known: the two tests of shared/mitsuba-tests/README.md ("acceptance rule") and their Welch
// counterparts for two renders that both come with a variance image.
//
// All the tests work on CIE XYZ values (unless options.colour is false): mean and variance
// images are converted from linear sRGB with Mitsuba 3's srgb_to_xyz matrix
// (include/mitsuba/core/spectrum.h; B. Lindbloom's sRGB/D65 matrix). As in Mitsuba's render test,
// the variance image is transformed with the same matrix (not its elementwise square) and then
// clamped to at least min_variance.
//
// Per-pixel rule (README test 1): one two-sided test per (pixel, channel); with
// alpha = 1 - (1 - family_alpha)^(1 / pixel_count) (Šidák), the image passes when the number
// of values with p > alpha is at least pass_fraction * 3 * pixel_count.
// Block rule (README test 2): img, reference and variance averaged over non-overlapping
// block x block cells (cells that would cross the right or bottom border are left out); one
// two-sided test per (cell, channel); passes when every p exceeds
// 1 - (1 - family_alpha)^(1 / (cells * 3)).
// Gain rule (ours, not in the README): the README's tests judge every pixel or block on its
// own, so a small uniform bias can hide below the noise of each (measured: a 2% scale of
// test_arealight at 868 spp passes both). The gain rule tests H0: E[img] = E[ref] against a
// global gain E[img] = k E[ref] with the matched filter, the weighted least-squares estimate
// of k - 1 with weights ref / v (v the variance of img - ref; Neyman–Pearson optimal for this
// alternative with known variances): per channel, Z = Σ (ref d / v) / sqrt(Σ ref² / v), d =
// img - ref, standard normal for an unbiased render because pixels are independent
// (independent sampler, box filter). The reference's own noise enters both ref and d; its
// covariance E[ref d] = -var / ref_spp is subtracted from the numerator. The three channels are
// tested two-sided at 1 - (1 - family_alpha)^(1/3). Any bias that mostly keeps one sign where
// the image is bright (a scale, a missing cosine) adds up in Z. The test resolves gains far
// below the accuracy of the references themselves (measured: a correct render of
// test_directional shows k = 1.0006, p = 2e-9, within the float32 accumulation and
// spectral-to-RGB differences of Mitsuba's reference), so it tests H0: |k - 1| <= gain_margin
// (default 0.5%, a quarter of the 2% it must catch) rather than k = 1. The weights must come from a
// well-converged reference: with a low-spp variance estimate in the weights, heavy-tailed
// pixels (high mean and high sample variance together) bias Z (measured: an apparent gain of
// 0.983 between a correct 868-spp render and the reference), so there is no Welch variant.
#pragma once

#include <string>
#include <vector>

#include "validation/image/rgb_image.h"

namespace tr {

struct VarianceTestOptions {
  double family_alpha = 0.01;
  double pass_fraction = 0.9975;  // per-pixel rule only
  double min_variance = 1e-4;     // XYZ variance clamp
  int block = 4;                  // block rule cell size in pixels
  double gain_margin = 0.005;     // gain rule: |k - 1| up to this counts as no bias
  // false: the three channels are not a colour (e.g. AOVs: albedo, position, depth and indices)
  // and are tested as they are, without the XYZ conversion; min_variance clamps them alike.
  bool colour = true;
};

struct HypothesisTestResult {
  std::string name;  // "pixel_z", "block_z", "gain_z", "pixel_welch", "block_welch", ...
  int block = 1;     // cell width in pixels; 1 for the per-pixel rule
  int cells_x = 0, cells_y = 0;
  double alpha = 0.0;              // per-value significance level (Šidák)
  double required_fraction = 1.0;  // of the values that must have p > alpha
  size_t values = 0;               // cells * 3
  size_t failing_values = 0;       // p <= alpha
  size_t failing_cells = 0;        // cells with at least one failing channel
  double min_p = 1.0;
  int min_p_x = -1, min_p_y = -1, min_p_channel = -1;  // cell coordinates; channel 0=X 1=Y 2=Z
  double max_statistic = 0.0;                          // largest |z| or |t|
  std::vector<float> statistic_map;                    // per cell: max over channels of |z| or |t|
  double gain[3] = {1.0, 1.0, 1.0};                    // gain tests: estimated k per channel
  bool passed = false;
};

// README test 1: z = |img - ref| sqrt(spp / var), var the reference's per-sample variance.
HypothesisTestResult pixel_z_test(const RgbImage& img, double spp, const RgbImage& ref,
                                  const RgbImage& ref_variance,
                                  const VarianceTestOptions& options = {});

// README test 2, with the variance of a block mean mean_block(var (1/spp + 1/ref_spp)) / 16
// generalised to block^2 pixels and any reference sample count.
HypothesisTestResult block_z_test(const RgbImage& img, double spp, const RgbImage& ref,
                                  const RgbImage& ref_variance, double ref_spp,
                                  const VarianceTestOptions& options = {});

// The gain rule with v = var (1/spp + 1/ref_spp), var the reference's per-sample variance.
HypothesisTestResult gain_z_test(const RgbImage& img, double spp, const RgbImage& ref,
                                 const RgbImage& ref_variance, double ref_spp,
                                 const VarianceTestOptions& options = {});

// Welch's unequal-variance t-test (Welch 1947), per pixel with the per-pixel rule:
// t = (a - b) / sqrt(va/na + vb/nb), Welch–Satterthwaite degrees of freedom
// (va/na + vb/nb)^2 / ((va/na)^2/(na-1) + (vb/nb)^2/(nb-1)). Needs na, nb > 1.
HypothesisTestResult pixel_welch_test(const RgbImage& a, const RgbImage& a_variance, double a_spp,
                                      const RgbImage& b, const RgbImage& b_variance, double b_spp,
                                      const VarianceTestOptions& options = {});

// Welch's test on block means with the block rule; a block mean of n spp is a mean of
// block^2 n samples with variance mean_block(v) / (block^2 n).
HypothesisTestResult block_welch_test(const RgbImage& a, const RgbImage& a_variance, double a_spp,
                                      const RgbImage& b, const RgbImage& b_variance, double b_spp,
                                      const VarianceTestOptions& options = {});

// Linear sRGB → CIE XYZ with Mitsuba 3's matrix (see above).
void srgb_to_xyz_mitsuba(const double rgb[3], double xyz[3]);

}  // namespace tr
