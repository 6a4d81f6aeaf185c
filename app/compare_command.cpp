#include "app/compare_command.h"

#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/heatmap.h"
#include "io/temp_file.h"
#include "validation/image/compare.h"

namespace tr {

namespace {

// The codes of app/exit_codes.h.
constexpr int kPass = 0, kFail = 1, kBadInput = 2, kOutputFailed = 5;

const char* kUsage = R"(usage: twinray compare A.exr B.exr [options]

Compares test image A with reference image B (EXR, PNG, JPEG, HDR, PFM, PPM, BMP or TGA; RGB
channels).

Inputs of the statistical tests:
  --var-a FILE          per-sample variance of A (e.g. a Mitsuba `moment` variance image, or
                        twinray's OUT_var.exr: see its twinray:variance_estimate)
  --var-b FILE          per-sample variance of B
  --spp-a N             samples per pixel of A
  --spp-b N             samples per pixel of B (32000 for the Mitsuba test references)
  --alpha A             family-wise significance level of each test (default 0.01)
  --pass-fraction F     per-pixel tests: required fraction of passing values (default 0.9975)
  --min-variance V      XYZ variance clamp (default 1e-4)
  --block N             block size of the block tests (default 4)
  --gain-margin M       gain test: |k - 1| <= M counts as no bias (default 0.005)

Lockstep agreement (two renders with the same sampler seed; always reported):
  --lockstep            make lockstep agreement decide the verdict
  --tolerance REL       relative tolerance per channel (default 1e-4)
  --abs-tolerance ABS   absolute tolerance per channel (default 1e-6)
  --lockstep-fraction F required fraction of pixels within tolerance (default 0.99)
  --rounding-control C  B's renderer on the same scene with its camera moved by one float
                        ulp: pixels of C off B by a quarter of their tolerance are rounding-
                        sensitive and left out of the cluster test
  --worst N             worst pixels / blocks listed (default 10)

Other criteria and outputs:
  --max-relmse X        fail when relMSE exceeds X
  --max-flip X          fail when the mean LDR-FLIP error exceeds X
  --ppd P               FLIP observer's pixels per degree (default 67.02)
  --heatmap OUT.png     false-colour (magma) per-pixel error map
  --heatmap-metric M    flip (default, on [0,1]), relerr (|a-b|/(|b|+0.01), on [0,R]) or
                        z (per-pixel |z| of the pixel test, saturating at its critical value)
  --heatmap-range R     upper end for relerr (default 0.1)
  --json OUT.json       JSON summary
  --quiet               print only the verdict line

Checks that decide the verdict:
  pixel_z, block_z  the two tests of the Mitsuba test-scene README (per pixel, per 4x4 block)
  gain_z            a matched-filter test for a global gain k != 1 (catches small uniform
                    biases the two README tests miss); all three need --var-b, --spp-a, --spp-b
                    and treat B as converged, so they do not run when --var-a is given
  pixel_welch, block_welch
                    Welch's t-test per pixel / per block for two noisy renders (--var-a and
                    --var-b, both sample counts)
  lockstep          with --lockstep;  max_relmse, max_flip  with --max-relmse / --max-flip
All tests are two-sided with Sidak-corrected levels; the JSON has every p-value. A's and B's
sample counts default to the twinray:spp metadata of the images when present.

Exit status: 0 pass (or no criterion requested), 1 fail, 2 bad input or usage,
5 an output file could not be written.
)";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double parse_number(const std::string& flag, const std::string& text) {
  try {
    size_t used = 0;
    double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw UsageError(flag + ": not a number: '" + text + "'");
}

double parse_positive(const std::string& flag, const std::string& text) {
  double v = parse_number(flag, text);
  if (!(v > 0.0)) throw UsageError(flag + ": must be positive");
  return v;
}

double parse_probability(const std::string& flag, const std::string& text) {
  double v = parse_number(flag, text);
  if (!(v > 0.0 && v < 1.0)) throw UsageError(flag + ": must lie strictly between 0 and 1");
  return v;
}

struct Arguments {
  std::vector<std::string> images;
  std::string var_a, var_b, rounding_control, heatmap, json;
  double spp_a = 0.0, spp_b = 0.0, heatmap_range = 0.1;
  HeatmapMetric heatmap_metric = HeatmapMetric::flip;
  bool quiet = false, help = false;
  CompareOptions options;
};

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    std::string flag = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(flag + ": missing value");
      return argv[++i];
    };
    if (flag == "--help" || flag == "-h")
      a.help = true;
    else if (flag == "--var-a")
      a.var_a = next();
    else if (flag == "--rounding-control")
      a.rounding_control = next();
    else if (flag == "--var-b")
      a.var_b = next();
    else if (flag == "--spp-a")
      a.spp_a = parse_positive(flag, next());
    else if (flag == "--spp-b")
      a.spp_b = parse_positive(flag, next());
    else if (flag == "--alpha")
      a.options.variance.family_alpha = a.options.lockstep_options.family_alpha =
          parse_probability(flag, next());
    else if (flag == "--pass-fraction")
      a.options.variance.pass_fraction = parse_probability(flag, next());
    else if (flag == "--gain-margin") {
      a.options.variance.gain_margin = parse_number(flag, next());
      if (a.options.variance.gain_margin < 0.0) throw UsageError(flag + ": must not be negative");
    } else if (flag == "--min-variance")
      a.options.variance.min_variance = parse_positive(flag, next());
    else if (flag == "--block") {
      double b = parse_positive(flag, next());
      if (b != int(b) || b < 2) throw UsageError(flag + ": must be an integer >= 2");
      a.options.variance.block = a.options.lockstep_options.block = int(b);
    } else if (flag == "--lockstep")
      a.options.lockstep = true;
    else if (flag == "--tolerance")
      a.options.lockstep_options.rel = parse_number(flag, next());
    else if (flag == "--abs-tolerance")
      a.options.lockstep_options.abs = parse_number(flag, next());
    else if (flag == "--lockstep-fraction") {
      double f = parse_number(flag, next());
      if (!(f > 0.0 && f <= 1.0)) throw UsageError(flag + ": must lie in (0, 1]");
      a.options.lockstep_options.required_fraction = f;
    } else if (flag == "--worst")
      a.options.lockstep_options.worst_count = int(parse_positive(flag, next()));
    else if (flag == "--max-relmse")
      a.options.max_relmse = parse_number(flag, next());
    else if (flag == "--max-flip")
      a.options.max_flip = parse_number(flag, next());
    else if (flag == "--ppd")
      a.options.pixels_per_degree = parse_positive(flag, next());
    else if (flag == "--heatmap")
      a.heatmap = next();
    else if (flag == "--heatmap-metric") {
      std::string m = next();
      if (m == "flip")
        a.heatmap_metric = HeatmapMetric::flip;
      else if (m == "relerr")
        a.heatmap_metric = HeatmapMetric::relative_error;
      else if (m == "z")
        a.heatmap_metric = HeatmapMetric::z;
      else
        throw UsageError(flag + ": expected flip, relerr or z, got '" + m + "'");
    } else if (flag == "--heatmap-range")
      a.heatmap_range = parse_positive(flag, next());
    else if (flag == "--json")
      a.json = next();
    else if (flag == "--quiet")
      a.quiet = true;
    else if (!flag.empty() && flag[0] == '-')
      throw UsageError("unknown option " + flag);
    else
      a.images.push_back(flag);
  }
  if (a.help) return a;
  if (a.images.size() != 2)
    throw UsageError("expected two images, got " + std::to_string(a.images.size()));
  if (a.options.lockstep_options.rel < 0.0 || a.options.lockstep_options.abs < 0.0)
    throw UsageError("tolerances must not be negative");
  if (!a.var_a.empty() && a.var_b.empty())
    throw UsageError("--var-a is used by the Welch tests, which also need --var-b");
  return a;
}

// The sample count a twinray render records in its metadata, or 0 without one.
double spp_from_metadata(const Image& img, const char* which, const char* flag, bool quiet) {
  auto it = img.metadata.find("twinray:spp");
  if (it == img.metadata.end()) return 0.0;
  double spp = parse_positive(std::string(which) + "'s twinray:spp metadata", it->second);
  if (!quiet)
    std::printf("spp-%c %g (from %s's twinray:spp metadata)\n", which[0] + 32, spp, which);
  return spp;
}

void print_test(const HypothesisTestResult& t) {
  if (t.name.rfind("gain", 0) == 0)
    std::printf("  %-12s %s  estimated gain X %.5f Y %.5f Z %.5f (alpha %.3g); min p %.3g\n",
                t.name.c_str(), t.passed ? "pass" : "FAIL", t.gain[0], t.gain[1], t.gain[2],
                t.alpha, t.min_p);
  else
    std::printf(
        "  %-12s %s  failing %zu/%zu values in %zu cells (alpha %.3g); min p %.3g at cell (%d, %d) "
        "%c\n",
        t.name.c_str(), t.passed ? "pass" : "FAIL", t.failing_values, t.values, t.failing_cells,
        t.alpha, t.min_p, t.min_p_x, t.min_p_y,
        t.min_p_channel >= 0 ? "XYZ"[t.min_p_channel] : '-');
}

void print_report(const CompareReport& r, const CompareOptions& o) {
  std::printf("%s vs %s (%dx%d)\n", r.test_name.c_str(), r.reference_name.c_str(), r.width,
              r.height);
  std::printf("  MSE %.6g  RMSE %.6g  relMSE %.6g  MAPE %.6g  PSNR %.3f dB\n", r.metrics.mse,
              r.metrics.rmse, r.metrics.relmse, r.metrics.mape, r.metrics.psnr);
  if (r.ssim)
    std::printf("  SSIM %.6f", r.ssim->mean);
  else
    std::printf("  SSIM n/a");
  std::printf("  LDR-FLIP mean %.6f (weighted median %.6f, max %.6f, %.2f ppd)\n", r.flip.mean,
              r.flip.weighted_median, r.flip.max, r.pixels_per_degree);
  for (const std::optional<HypothesisTestResult>* t : r.tests())
    if (*t) print_test(**t);
  const LockstepResult& l = r.lockstep;
  std::printf(
      "  lockstep     %s  %.6f of pixels within rel %.3g abs %.3g; %zu systematic, %zu clustered "
      "windows%s\n",
      !r.lockstep_decides ? "info"
      : l.passed          ? "pass"
                          : "FAIL",
      l.fraction_within, o.lockstep_options.rel, o.lockstep_options.abs, l.systematic_cells,
      l.clustered_windows, r.lockstep_decides ? "" : " (not a criterion without --lockstep)");
  if (l.rounding_controlled)
    std::printf("               %zu rounding-sensitive pixels (left out of the cluster test)\n",
                l.rounding_sensitive);
  if (r.lockstep_decides)
    for (const LockstepPixel& p : l.worst)
      if (p.excess > 1.0)
        std::printf("    pixel (%d, %d) excess %.3g: A (%.6g %.6g %.6g) B (%.6g %.6g %.6g)\n", p.x,
                    p.y, p.excess, p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
  for (const std::string& n : r.notes) std::printf("  note: %s\n", n.c_str());
}

}  // namespace

int compare_command(int argc, char** argv) {
  Arguments args;
  try {
    args = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "twinray compare: %s\n(see twinray compare --help)\n", e.what());
    return kBadInput;
  }
  if (args.help) {
    std::fputs(kUsage, stdout);
    return kPass;
  }
  CompareInputs in;
  try {
    in.test_name = args.images[0];
    in.reference_name = args.images[1];
    Image a = read_image(args.images[0]), b = read_image(args.images[1]);
    in.test = to_rgb(a, args.images[0]);
    in.reference = to_rgb(b, args.images[1]);
    if (!args.var_a.empty()) in.test_variance = read_rgb(args.var_a);
    if (!args.var_b.empty()) in.reference_variance = read_rgb(args.var_b);
    if (!args.rounding_control.empty()) in.rounding_control = read_rgb(args.rounding_control);
    in.test_spp = args.spp_a > 0.0 ? args.spp_a : spp_from_metadata(a, "A", "--spp-a", args.quiet);
    in.reference_spp =
        args.spp_b > 0.0 ? args.spp_b : spp_from_metadata(b, "B", "--spp-b", args.quiet);
    if (in.reference_variance && in.test_spp == 0.0)
      throw UsageError("--var-b needs A's sample count (--spp-a or twinray:spp metadata)");
    if (in.test_variance && (in.test_spp == 0.0 || in.reference_spp == 0.0))
      throw UsageError("the Welch tests need both sample counts (--spp-a, --spp-b)");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "twinray compare: %s\n", e.what());
    return kBadInput;
  }

  CompareReport report;
  try {
    report = compare_images(in, args.options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "twinray compare: %s\n", e.what());
    return kBadInput;
  }
  if (!args.quiet) print_report(report, args.options);
  try {
    if (!args.heatmap.empty()) {
      float lo, hi;
      std::vector<float> v =
          heatmap_values(report, in, args.heatmap_metric, args.heatmap_range, &lo, &hi);
      write_heatmap_png(args.heatmap, in.test.width, in.test.height, v, lo, hi);
    }
    if (!args.json.empty()) write_text_file(args.json, compare_report_json(report, args.options));
  } catch (const FileError& e) {
    std::fprintf(stderr, "twinray compare: %s\n", e.what());
    return kOutputFailed;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "twinray compare: %s\n", e.what());
    return kBadInput;
  }
  if (report.criteria.empty()) {
    std::printf("verdict: no criteria (metrics only; give variances/spp, --lockstep or a max)\n");
    return kPass;
  }
  std::printf("verdict: %s\n", report.passed ? "PASS" : "FAIL");
  for (const std::string& f : report.failures) std::printf("  failed %s\n", f.c_str());
  return report.passed ? kPass : kFail;
}

}  // namespace tr
