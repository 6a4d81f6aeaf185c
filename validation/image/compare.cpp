#include "validation/image/compare.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "validation/image/json_writer.h"
#include "validation/image/statistics.h"

namespace tr {

namespace {

std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

void decide(CompareReport& r, const std::string& criterion, bool ok, const std::string& why) {
  r.criteria.push_back(criterion);
  if (!ok) r.failures.push_back(criterion + ": " + why);
}

std::string describe(const HypothesisTestResult& t) {
  std::string s = std::to_string(t.failing_values) + " of " + std::to_string(t.values) +
                  " values with p <= " + format("%.3g", t.alpha) + ", in " +
                  std::to_string(t.failing_cells) + " cells";
  if (t.min_p_channel >= 0)
    s += "; min p " + format("%.3g", t.min_p) + " at cell (" + std::to_string(t.min_p_x) + ", " +
         std::to_string(t.min_p_y) + ") channel " + "XYZ"[t.min_p_channel];
  return s;
}

}  // namespace

CompareReport compare_images(const CompareInputs& in, const CompareOptions& options) {
  check_same_size(in.reference, in.reference_name, in.test, in.test_name);
  if (in.test_variance)
    check_same_size(in.test, in.test_name, *in.test_variance, "variance of " + in.test_name);
  if (in.reference_variance)
    check_same_size(in.test, in.test_name, *in.reference_variance,
                    "variance of " + in.reference_name);

  CompareReport r;
  r.test_name = in.test_name;
  r.reference_name = in.reference_name;
  r.width = in.test.width;
  r.height = in.test.height;
  r.metrics = error_metrics(in.test, in.reference);
  if (in.test.width >= kSsimWindow && in.test.height >= kSsimWindow)
    r.ssim = ssim(in.test, in.reference);
  else
    r.notes.push_back("ssim: not computed, the image is smaller than the 11x11 window");
  r.pixels_per_degree = options.pixels_per_degree;
  r.flip = ldr_flip(in.test, in.reference, options.pixels_per_degree);
  r.lockstep = lockstep_compare(in.test, in.reference, options.lockstep_options,
                                in.rounding_control ? &*in.rounding_control : nullptr);
  r.lockstep_decides = options.lockstep;

  const VarianceTestOptions& vo = options.variance;
  const int block = vo.block;
  const bool fits_block = in.test.width >= block && in.test.height >= block;
  if (in.test_variance) {
    r.notes.push_back(
        "pixel_z, block_z, gain_z: not run, A has its own variance (Welch's tests compare two "
        "noisy renders; the z-tests treat B as converged)");
  } else if (in.reference_variance && in.test_spp > 0.0) {
    r.pixel_z = pixel_z_test(in.test, in.test_spp, in.reference, *in.reference_variance, vo);
    if (in.reference_spp > 0.0) {
      r.gain_z = gain_z_test(in.test, in.test_spp, in.reference, *in.reference_variance,
                             in.reference_spp, vo);
      if (fits_block)
        r.block_z = block_z_test(in.test, in.test_spp, in.reference, *in.reference_variance,
                                 in.reference_spp, vo);
      else
        r.notes.push_back("block_z: image smaller than one block");
    } else {
      r.notes.push_back("block_z, gain_z: need the reference's sample count");
    }
  } else {
    r.notes.push_back(
        "pixel_z, block_z, gain_z: need the reference's variance and the test's sample count");
  }
  if (in.test_variance && in.reference_variance && in.test_spp > 1.0 && in.reference_spp > 1.0) {
    r.pixel_welch = pixel_welch_test(in.test, *in.test_variance, in.test_spp, in.reference,
                                     *in.reference_variance, in.reference_spp, vo);
    if (fits_block)
      r.block_welch = block_welch_test(in.test, *in.test_variance, in.test_spp, in.reference,
                                       *in.reference_variance, in.reference_spp, vo);
  } else {
    r.notes.push_back("pixel_welch, block_welch: need both variances and both sample counts (> 1)");
  }

  for (const std::optional<HypothesisTestResult>* t : r.tests())
    if (*t) decide(r, (*t)->name, (*t)->passed, describe(**t));
  if (options.lockstep) {
    const LockstepResult& l = r.lockstep;
    std::string why =
        format("%.6f of pixels within tolerance (need %.6f), ", l.fraction_within,
               options.lockstep_options.required_fraction) +
        format("%.0f windows with a systematic difference, ", double(l.systematic_cells)) +
        format("%.0f with clustered differences", double(l.clustered_windows));
    decide(r, "lockstep", l.passed, why);
  }
  if (options.max_relmse)
    decide(r, "max_relmse", r.metrics.relmse <= *options.max_relmse,
           format("relMSE %.6g > %.6g", r.metrics.relmse, *options.max_relmse));
  if (options.max_flip)
    decide(r, "max_flip", r.flip.mean <= *options.max_flip,
           format("mean FLIP %.6g > %.6g", r.flip.mean, *options.max_flip));
  r.passed = r.failures.empty();
  return r;
}

namespace {

void write_test(JsonWriter& j, const HypothesisTestResult& t, double family_alpha,
                double gain_margin) {
  const char* channels[3] = {"X", "Y", "Z"};
  j.begin_object()
      .field("passed", t.passed)
      .field("block", t.block)
      .field("cells_x", t.cells_x)
      .field("cells_y", t.cells_y)
      .field("family_alpha", family_alpha)
      .field("alpha", t.alpha)
      .field("required_fraction", t.required_fraction)
      .field("values", std::uint64_t(t.values))
      .field("failing_values", std::uint64_t(t.failing_values))
      .field("failing_cells", std::uint64_t(t.failing_cells))
      .field("passing_fraction",
             t.values ? double(t.values - t.failing_values) / double(t.values) : 0.0)
      .field("min_p", t.min_p)
      .field("max_statistic", t.max_statistic);
  if (t.name.rfind("gain", 0) == 0) {
    j.key("gain_xyz").begin_array().value(t.gain[0]).value(t.gain[1]).value(t.gain[2]).end_array();
    j.field("gain_margin", gain_margin);
  }
  j.key("min_p_at").begin_object();
  if (t.min_p_channel >= 0)
    j.field("cell_x", t.min_p_x)
        .field("cell_y", t.min_p_y)
        .field("pixel_x", t.min_p_x * t.block)
        .field("pixel_y", t.min_p_y * t.block)
        .field("channel", channels[t.min_p_channel]);
  j.end_object();
  j.end_object();
}

void write_strings(JsonWriter& j, const std::string& name, const std::vector<std::string>& v) {
  j.key(name).begin_array();
  for (const std::string& s : v) j.value(s);
  j.end_array();
}

}  // namespace

std::string compare_report_json(const CompareReport& r, const CompareOptions& options) {
  JsonWriter j;
  j.begin_object()
      .field("test", r.test_name)
      .field("reference", r.reference_name)
      .field("width", r.width)
      .field("height", r.height)
      .field("verdict", r.criteria.empty() ? "no-criteria"
                        : r.passed         ? "pass"
                                           : "fail")
      .field("passed", r.passed);
  write_strings(j, "criteria", r.criteria);
  write_strings(j, "failures", r.failures);
  write_strings(j, "notes", r.notes);

  j.key("metrics").begin_object();
  j.field("mse", r.metrics.mse)
      .field("rmse", r.metrics.rmse)
      .field("relmse", r.metrics.relmse)
      .field("relmse_epsilon", kRelMseEpsilon)
      .field("mape", r.metrics.mape)
      .field("mape_epsilon", kMapeEpsilon)
      .field("psnr_db", r.metrics.psnr);
  j.key("ssim");
  if (r.ssim)
    j.value(r.ssim->mean);
  else
    j.null();
  j.key("flip").begin_object();
  j.field("mean", r.flip.mean)
      .field("weighted_median", r.flip.weighted_median)
      .field("weighted_quartile1", r.flip.weighted_quartile1)
      .field("weighted_quartile3", r.flip.weighted_quartile3)
      .field("min", r.flip.min)
      .field("max", r.flip.max)
      .field("pixels_per_degree", r.pixels_per_degree);
  j.end_object();
  j.end_object();

  j.key("tests").begin_object();
  for (const std::optional<HypothesisTestResult>* t : r.tests())
    if (*t) {
      j.key((*t)->name);
      write_test(j, **t, options.variance.family_alpha, options.variance.gain_margin);
    }
  j.end_object();

  const LockstepResult& l = r.lockstep;
  const LockstepOptions& lo = options.lockstep_options;
  j.key("lockstep").begin_object();
  j.field("decides_verdict", r.lockstep_decides)
      .field("passed", l.passed)
      .field("rel_tolerance", lo.rel)
      .field("abs_tolerance", lo.abs)
      .field("required_fraction", lo.required_fraction)
      .field("fraction_within", l.fraction_within)
      .field("pixels_outside", std::uint64_t(l.pixels_outside))
      .field("max_abs_difference", l.max_abs_difference)
      .field("block", lo.block)
      .field("block_alpha", l.block_alpha)
      .field("systematic_cells", std::uint64_t(l.systematic_cells))
      .field("clustered_windows", std::uint64_t(l.clustered_windows))
      .field("rounding_sensitive_pixels", std::uint64_t(l.rounding_sensitive))
      .field("most_outside_in_window", l.most_outside);
  j.key("worst_pixels").begin_array();
  for (const LockstepPixel& p : l.worst) {
    j.begin_object().field("x", p.x).field("y", p.y).field("excess", p.excess);
    j.key("a").begin_array().value(p.a[0]).value(p.a[1]).value(p.a[2]).end_array();
    j.key("b").begin_array().value(p.b[0]).value(p.b[1]).value(p.b[2]).end_array();
    j.end_object();
  }
  j.end_array();
  j.key("systematic_blocks").begin_array();
  for (const LockstepBlock& b : l.worst_blocks)
    j.begin_object()
        .field("x", b.x)
        .field("y", b.y)
        .field("channel", std::string(1, "RGB"[b.channel]))
        .field("mean_difference", b.mean_difference)
        .field("t", b.t)
        .field("p", b.p)
        .end_object();
  j.end_array();
  j.end_object();
  j.end_object();
  return j.str() + "\n";
}

std::vector<float> heatmap_values(const CompareReport& report, const CompareInputs& inputs,
                                  HeatmapMetric metric, double relative_range, float* lo,
                                  float* hi) {
  *lo = 0.0f;
  switch (metric) {
    case HeatmapMetric::flip:
      *hi = 1.0f;
      return report.flip.map;
    case HeatmapMetric::relative_error: {
      *hi = float(relative_range);
      std::vector<float> v(inputs.test.pixel_count());
      for (size_t i = 0; i < v.size(); ++i) {
        double sum = 0.0;
        for (int c = 0; c < 3; ++c) {
          double a = inputs.test.rgb[3 * i + c], b = inputs.reference.rgb[3 * i + c];
          sum += std::fabs(a - b) / (std::fabs(b) + kMapeEpsilon);
        }
        v[i] = float(sum / 3.0);
      }
      return v;
    }
    case HeatmapMetric::z: {
      const std::optional<HypothesisTestResult>& t =
          report.pixel_z ? report.pixel_z : report.pixel_welch;
      if (!t)
        throw std::invalid_argument(
            "the z heatmap needs a per-pixel hypothesis test (variances and sample counts)");
      *hi = float(normal_two_sided_quantile(t->alpha));
      return t->statistic_map;
    }
  }
  throw std::invalid_argument("unknown heatmap metric");
}

}  // namespace tr
