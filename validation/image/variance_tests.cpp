#include "validation/image/variance_tests.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "validation/image/statistics.h"

namespace tr {

void srgb_to_xyz_mitsuba(const double rgb[3], double xyz[3]) {
  static const double m[3][3] = {{0.412453, 0.357580, 0.180423},
                                 {0.212671, 0.715160, 0.072169},
                                 {0.019334, 0.119193, 0.950227}};
  for (int i = 0; i < 3; ++i) xyz[i] = m[i][0] * rgb[0] + m[i][1] * rgb[1] + m[i][2] * rgb[2];
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The values the tests compare: XYZ for a colour image, the channels as they are otherwise.
RgbImage tested_values(const RgbImage& rgb, const VarianceTestOptions& options) {
  if (!options.colour) return rgb;
  RgbImage xyz = rgb;
  for (size_t i = 0; i < rgb.pixel_count(); ++i)
    srgb_to_xyz_mitsuba(&rgb.rgb[3 * i], &xyz.rgb[3 * i]);
  return xyz;
}

RgbImage clamped_tested_variance(const RgbImage& rgb, const VarianceTestOptions& options) {
  RgbImage xyz = tested_values(rgb, options);
  for (double& v : xyz.rgb) v = std::max(v, options.min_variance);
  return xyz;
}

// Averages over non-overlapping block x block cells; partial cells at the borders are dropped.
RgbImage block_means(const RgbImage& img, int block) {
  RgbImage out;
  out.width = img.width / block;
  out.height = img.height / block;
  out.rgb.assign(3 * out.pixel_count(), 0.0);
  for (int by = 0; by < out.height; ++by)
    for (int bx = 0; bx < out.width; ++bx)
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int y = 0; y < block; ++y)
          for (int x = 0; x < block; ++x) sum += img.at(bx * block + x, by * block + y, c);
        out.at(bx, by, c) = sum / (block * block);
      }
  return out;
}

RgbImage filled_like(const RgbImage& shape, double value) {
  RgbImage out = shape;
  std::fill(out.rgb.begin(), out.rgb.end(), value);
  return out;
}

// Per (cell, channel): difference of means, variance of that difference, degrees of freedom.
struct Differences {
  RgbImage delta, variance, dof;
};

HypothesisTestResult evaluate(const std::string& name, int block, const Differences& d,
                              double alpha, double required_fraction) {
  HypothesisTestResult r;
  r.name = name;
  r.block = block;
  r.cells_x = d.delta.width;
  r.cells_y = d.delta.height;
  r.alpha = alpha;
  r.required_fraction = required_fraction;
  r.values = 3 * d.delta.pixel_count();
  r.statistic_map.assign(d.delta.pixel_count(), 0.0f);
  for (int y = 0; y < r.cells_y; ++y)
    for (int x = 0; x < r.cells_x; ++x) {
      bool cell_fails = false;
      for (int c = 0; c < 3; ++c) {
        double statistic = std::fabs(d.delta.at(x, y, c)) / std::sqrt(d.variance.at(x, y, c));
        if (std::isnan(statistic))
          throw std::invalid_argument(name + ": NaN test statistic at cell (" + std::to_string(x) +
                                      ", " + std::to_string(y) +
                                      "): the images hold NaN or negative variances");
        double p = student_two_sided_p(statistic, d.dof.at(x, y, c));
        if (p <= alpha) {
          ++r.failing_values;
          cell_fails = true;
        }
        if (p < r.min_p || r.min_p_x < 0) {
          r.min_p = p;
          r.min_p_x = x;
          r.min_p_y = y;
          r.min_p_channel = c;
        }
        r.max_statistic = std::max(r.max_statistic, statistic);
        float& shown = r.statistic_map[size_t(y) * r.cells_x + x];
        shown = std::max(shown, float(statistic));
      }
      if (cell_fails) ++r.failing_cells;
    }
  double passing = double(r.values - r.failing_values);
  r.passed = r.values > 0 && passing >= required_fraction * double(r.values);
  return r;
}

// The gain rule (see variance_tests.h): per channel, with weights w = r / v,
// Z = (Σ w d - Σ bias / v) / sqrt(Σ w² v), where bias = E0[r d] is the covariance that the
// regressor r shares with d through their common noise, so that E0[Z] = 0 and Var0[Z] = 1.
// (Σ w d - Σ bias / v) / Σ w² v estimates k - 1.
HypothesisTestResult gain_test(const std::string& name, const RgbImage& d, const RgbImage& v,
                               const RgbImage& r, const RgbImage& bias, double family_alpha,
                               double margin) {
  double numerator[3] = {0, 0, 0}, information[3] = {0, 0, 0};
  for (size_t i = 0; i < d.rgb.size(); ++i) {
    numerator[i % 3] += (r.rgb[i] * d.rgb[i] - bias.rgb[i]) / v.rgb[i];
    information[i % 3] += r.rgb[i] * r.rgb[i] / v.rgb[i];
  }
  Differences combined;
  combined.delta = RgbImage{1, 1, {0.0, 0.0, 0.0}};
  combined.variance = combined.delta;
  // With k̂ - 1 = numerator / information and SE(k̂) = 1 / sqrt(information), the statistic
  // max(0, |k̂ - 1| - margin) / SE tests H0: |k - 1| <= margin; its two-sided normal p-value
  // bounds the size at the boundary k - 1 = ±margin (Φc(z) + Φc(z + 2 margin / SE) <= 2 Φc(z)).
  for (int c = 0; c < 3; ++c) {
    combined.delta.rgb[c] = std::max(0.0, std::fabs(numerator[c]) - margin * information[c]);
    combined.variance.rgb[c] = information[c];
  }
  combined.dof = filled_like(combined.delta, kInfinity);
  HypothesisTestResult result =
      evaluate(name, d.width, combined, sidak_alpha(family_alpha, 3.0), 1.0);
  // The estimated gain per channel, k - 1 = numerator / information, for the report.
  for (int c = 0; c < 3; ++c)
    result.gain[c] = information[c] > 0.0 ? 1.0 + numerator[c] / information[c] : 1.0;
  return result;
}

void check_inputs(const RgbImage& img, const std::vector<const RgbImage*>& others,
                  const std::vector<double>& spps) {
  for (const RgbImage* o : others) check_same_size(img, "image", *o, "comparison input");
  for (double spp : spps)
    if (!(spp > 0.0) || std::isinf(spp))
      throw std::invalid_argument("sample counts must be positive and finite");
}

}  // namespace

HypothesisTestResult pixel_z_test(const RgbImage& img, double spp, const RgbImage& ref,
                                  const RgbImage& ref_variance,
                                  const VarianceTestOptions& options) {
  check_inputs(img, {&ref, &ref_variance}, {spp});
  Differences d;
  d.delta = tested_values(img, options);
  RgbImage ref_xyz = tested_values(ref, options);
  d.variance = clamped_tested_variance(ref_variance, options);
  for (size_t i = 0; i < d.delta.rgb.size(); ++i) {
    d.delta.rgb[i] -= ref_xyz.rgb[i];
    d.variance.rgb[i] /= spp;  // z = |img - ref| sqrt(spp / var)
  }
  d.dof = filled_like(d.delta, kInfinity);
  return evaluate("pixel_z", 1, d, sidak_alpha(options.family_alpha, double(img.pixel_count())),
                  options.pass_fraction);
}

HypothesisTestResult block_z_test(const RgbImage& img, double spp, const RgbImage& ref,
                                  const RgbImage& ref_variance, double ref_spp,
                                  const VarianceTestOptions& options) {
  check_inputs(img, {&ref, &ref_variance}, {spp, ref_spp});
  const int block = options.block;
  if (block < 1 || img.width < block || img.height < block)
    throw std::invalid_argument("image smaller than one block");
  Differences d;
  d.delta = block_means(tested_values(img, options), block);
  RgbImage ref_mean = block_means(tested_values(ref, options), block);
  d.variance = block_means(clamped_tested_variance(ref_variance, options), block);
  for (size_t i = 0; i < d.delta.rgb.size(); ++i) {
    d.delta.rgb[i] -= ref_mean.rgb[i];
    // Variance of a block mean: mean_block(var (1/spp + 1/ref_spp)) / block².
    d.variance.rgb[i] *= (1.0 / spp + 1.0 / ref_spp) / (block * block);
  }
  d.dof = filled_like(d.delta, kInfinity);
  double values = 3.0 * double(d.delta.pixel_count());
  return evaluate("block_z", block, d, sidak_alpha(options.family_alpha, values), 1.0);
}

HypothesisTestResult gain_z_test(const RgbImage& img, double spp, const RgbImage& ref,
                                 const RgbImage& ref_variance, double ref_spp,
                                 const VarianceTestOptions& options) {
  check_inputs(img, {&ref, &ref_variance}, {spp, ref_spp});
  RgbImage d = tested_values(img, options), r = tested_values(ref, options),
           v = tested_values(ref_variance, options), bias = v;
  for (size_t i = 0; i < d.rgb.size(); ++i) {
    d.rgb[i] -= r.rgb[i];
    // d contains the reference's noise with a minus sign: E0[r d] = -var / ref_spp.
    bias.rgb[i] = -std::max(v.rgb[i], 0.0) / ref_spp;
    v.rgb[i] = std::max(v.rgb[i], options.min_variance) * (1.0 / spp + 1.0 / ref_spp);
  }
  return gain_test("gain_z", d, v, r, bias, options.family_alpha, options.gain_margin);
}

namespace {

// Welch's t-test for means of na and nb samples with per-sample variances va and vb.
void welch(double va, double na, double vb, double nb, double* variance, double* dof) {
  double sa = va / na, sb = vb / nb;
  *variance = sa + sb;
  *dof = (sa + sb) * (sa + sb) / (sa * sa / (na - 1.0) + sb * sb / (nb - 1.0));
}

Differences welch_differences(int block, const RgbImage& a, const RgbImage& a_variance,
                              double a_spp, const RgbImage& b, const RgbImage& b_variance,
                              double b_spp, const VarianceTestOptions& options) {
  Differences d;
  d.delta = block_means(tested_values(a, options), block);
  RgbImage b_mean = block_means(tested_values(b, options), block);
  RgbImage va = block_means(clamped_tested_variance(a_variance, options), block);
  RgbImage vb = block_means(clamped_tested_variance(b_variance, options), block);
  d.variance = d.delta;
  d.dof = d.delta;
  const double samples_per_cell = double(block) * block;
  for (size_t i = 0; i < d.delta.rgb.size(); ++i) {
    d.delta.rgb[i] -= b_mean.rgb[i];
    welch(va.rgb[i], samples_per_cell * a_spp, vb.rgb[i], samples_per_cell * b_spp,
          &d.variance.rgb[i], &d.dof.rgb[i]);
  }
  return d;
}

HypothesisTestResult welch_test(const std::string& name, int block, const RgbImage& a,
                                const RgbImage& a_variance, double a_spp, const RgbImage& b,
                                const RgbImage& b_variance, double b_spp, double alpha,
                                double required_fraction, const VarianceTestOptions& options) {
  if (!(a_spp > 1.0 && b_spp > 1.0))
    throw std::invalid_argument("Welch's test needs more than one sample per pixel on each side");
  Differences d = welch_differences(block, a, a_variance, a_spp, b, b_variance, b_spp, options);
  return evaluate(name, block, d, alpha, required_fraction);
}

}  // namespace

HypothesisTestResult pixel_welch_test(const RgbImage& a, const RgbImage& a_variance, double a_spp,
                                      const RgbImage& b, const RgbImage& b_variance, double b_spp,
                                      const VarianceTestOptions& options) {
  check_inputs(a, {&a_variance, &b, &b_variance}, {a_spp, b_spp});
  return welch_test("pixel_welch", 1, a, a_variance, a_spp, b, b_variance, b_spp,
                    sidak_alpha(options.family_alpha, double(a.pixel_count())),
                    options.pass_fraction, options);
}

HypothesisTestResult block_welch_test(const RgbImage& a, const RgbImage& a_variance, double a_spp,
                                      const RgbImage& b, const RgbImage& b_variance, double b_spp,
                                      const VarianceTestOptions& options) {
  check_inputs(a, {&a_variance, &b, &b_variance}, {a_spp, b_spp});
  const int block = options.block;
  if (block < 1 || a.width < block || a.height < block)
    throw std::invalid_argument("image smaller than one block");
  double cells = double(a.width / block) * double(a.height / block);
  return welch_test("block_welch", block, a, a_variance, a_spp, b, b_variance, b_spp,
                    sidak_alpha(options.family_alpha, 3.0 * cells), 1.0, options);
}

}  // namespace tr
