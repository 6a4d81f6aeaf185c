#include "app/validate_command.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "app/run_backend.h"
#include "io/heatmap.h"
#include "io/temp_file.h"
#include "render/write_result.h"
#include "validation/harness/mitsuba_acceptance.h"
#include "validation/harness/scene_render.h"
#include "validation/harness/suite.h"
#include "validation/image/html_report.h"
#include "validation/image/json_writer.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

const char* kUsage = R"(usage: twinray validate SUITE [options]

Renders every scene of SUITE (format: validation/harness/suite.h; validation/suites/ has the
Mitsuba test scenes) and judges each render against the scene's reference: the per-pixel and
per-4x4-block z-tests of shared/mitsuba-tests/README.md and the gain test (a global scale;
validation/image/variance_tests.h), each at family-wise alpha 0.01. With the GPU backend, the
GPU render is judged the same way and compared with the CPU render of the same seed: lockstep
agreement (every pixel within relative 1e-4) and Welch's t-tests per pixel and per block.
A render that fails against the reference is judged again by a confirmation render of its
backend, another seed at 4x the samples, which then decides (a right renderer fails the rule
in about 1% of runs by chance; a bias fails both, the second more surely).

Options:
  --out DIR            output folder (default: validate-<suite name>); it receives
                       report.html (self-contained), summary.json and the images
  --gpu                also render on the GPU; a scene fails when the GPU cannot render it
  --gpu-if-available   also render on the GPU when a usable device exists
  --only NAME          validate only this scene of the suite (may repeat)
  --spp N              samples per pixel for every scene (default: the suite's)
  --threads N          CPU worker threads (default: all cores)

Exit status: 0 every scene passed, 1 a check failed or a scene could not be rendered,
2 usage or suite error, 5 an output could not be written.
)";

enum class GpuMode { off, required, if_available };

struct ValidateArgs {
  std::string suite, out;
  GpuMode gpu = GpuMode::off;
  std::set<std::string> only;
  std::uint32_t spp = 0, threads = 0;
  bool help = false;
};

ValidateArgs parse(int argc, char** argv) {
  ValidateArgs a;
  Arguments args(argc - 1, argv + 1);
  while (args.more()) {
    std::string arg = args.next();
    if (arg == "--help" || arg == "-h") {
      a.help = true;
    } else if (arg == "--out") {
      a.out = args.value(arg);
    } else if (arg == "--gpu") {
      a.gpu = GpuMode::required;
    } else if (arg == "--gpu-if-available") {
      a.gpu = GpuMode::if_available;
    } else if (arg == "--only") {
      a.only.insert(args.value(arg));
    } else if (arg == "--spp") {
      a.spp = args.uint_value(arg, 1);
    } else if (arg == "--threads") {
      a.threads = args.uint_value(arg, 1);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.suite.empty()) {
      a.suite = arg;
    } else {
      throw UsageError("more than one suite given ('" + a.suite + "', '" + arg + "')");
    }
  }
  if (!a.help && a.suite.empty()) throw UsageError("no suite file given");
  if (a.out.empty()) a.out = "validate-" + fs::path(a.suite).stem().string();
  return a;
}

struct Comparison {
  ReportComparison shown;
  CompareOptions options;
  bool rejudged = false;  // failed; a confirmation render decides in its place
};

// Renders a comparison's heatmaps next to the report: |z| (or Welch |t|) of the per-pixel test
// and the relative error, plus lockstep excess for same-seed renders.
void add_heatmaps(Comparison& c, const CompareInputs& in, const std::string& stem) {
  float lo = 0.0f, hi = 1.0f;
  std::string z_png = stem + "_z.png";
  write_heatmap_png(z_png, in.test.width, in.test.height,
                    heatmap_values(c.shown.report, in, HeatmapMetric::z, 0.0, &lo, &hi), lo, hi);
  c.shown.heatmaps.push_back({"per-pixel |z| (saturates at the test's critical value)", z_png});
  std::string rel_png = stem + "_relerr.png";
  write_heatmap_png(
      rel_png, in.test.width, in.test.height,
      heatmap_values(c.shown.report, in, HeatmapMetric::relative_error, 0.1, &lo, &hi), lo, hi);
  c.shown.heatmaps.push_back({"relative error |a-b|/(|b|+0.01), 0 to 0.1", rel_png});
  if (c.options.lockstep) {
    std::string ls_png = stem + "_lockstep.png";
    write_heatmap_png(ls_png, in.test.width, in.test.height, c.shown.report.lockstep.excess_map,
                      0.0f, 2.0f);
    c.shown.heatmaps.push_back({"lockstep excess (> 1 is outside the tolerance), 0 to 2", ls_png});
  }
}

Comparison against_reference(const std::string& title, const SceneRender& r, std::uint32_t spp,
                             const SuiteEntry& e, const RgbImage& ref, const RgbImage& var,
                             const std::string& stem) {
  CompareInputs in;
  in.test_name = title.substr(0, title.find(' '));
  in.reference_name = "Mitsuba reference";
  in.test = r.mean;
  in.reference = ref;
  in.reference_variance = var;
  in.test_spp = spp;
  in.reference_spp = e.reference_spp;
  Comparison c;
  c.shown.title = title;
  c.shown.report = compare_images(in, c.options);
  add_heatmaps(c, in, stem);
  return c;
}

Comparison between_backends(const SceneRender& gpu, const SceneRender& cpu, std::uint32_t spp,
                            const std::string& stem) {
  CompareInputs in;
  in.test_name = "GPU";
  in.reference_name = "CPU";
  in.test = gpu.mean;
  in.test_variance = gpu.variance;
  in.reference = cpu.mean;
  in.reference_variance = cpu.variance;
  in.test_spp = in.reference_spp = spp;
  Comparison c;
  c.options.lockstep = true;
  c.shown.title = "GPU vs CPU (same seed): lockstep and Welch";
  c.shown.report = compare_images(in, c.options);
  add_heatmaps(c, in, stem);
  return c;
}

struct SceneOutcome {
  ReportScene scene;
  std::uint32_t spp = 0;
  std::vector<Comparison> comparisons;
};

// `backend`'s render r judged against the reference; a failure is judged again by a
// confirmation render (validation/harness/mitsuba_acceptance.h), both kept in the report.
void judge_against_reference(SceneOutcome& o, const std::string& backend, const Scene& scene,
                             const SceneRender& r, std::uint32_t seed, const SuiteEntry& e,
                             const RgbImage& ref, const RgbImage& var, const std::string& stem,
                             std::uint32_t threads) {
  const std::string title =
      backend == "cpu" ? "CPU vs Mitsuba reference" : "GPU vs Mitsuba reference";
  o.comparisons.push_back(
      against_reference(title, r, o.spp, e, ref, var, stem + "_" + backend + "_ref"));
  if (o.comparisons.back().shown.report.passed) return;
  o.comparisons.back().rejudged = true;
  o.comparisons.back().shown.title += " (failed: the confirmation below decides)";
  const std::uint32_t spp = o.spp * kConfirmationSppFactor, again = confirmation_seed(seed);
  SceneRender c = render_scene(run_backend, backend, scene, spp, again, threads);
  o.comparisons.push_back(against_reference(
      title + ": confirmation, seed " + std::to_string(again) + ", " + std::to_string(spp) + " spp",
      c, spp, e, ref, var, stem + "_" + backend + "_confirm"));
}

void print_comparison(const Comparison& c) {
  const CompareReport& r = c.shown.report;
  std::printf("  %s: %s (RMSE %.4g, relMSE %.4g)\n", c.shown.title.c_str(),
              r.passed ? "pass" : "FAIL", r.metrics.rmse, r.metrics.relmse);
  for (const std::optional<HypothesisTestResult>* t : r.tests())
    if (*t) std::printf("    %s\n", describe_test(**t).c_str());
  if (r.lockstep_decides)
    std::printf(
        "    lockstep    %s  %.6f of pixels within tolerance, %zu systematic, %zu clustered "
        "windows\n",
        r.lockstep.passed ? "pass" : "FAIL", r.lockstep.fraction_within,
        r.lockstep.systematic_cells, r.lockstep.clustered_windows);
  for (const std::string& f : r.failures) std::printf("    failure: %s\n", f.c_str());
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f s", s);
  return buf;
}

SceneOutcome validate_scene(const SuiteEntry& e, const ValidateArgs& a, const fs::path& dir) {
  SceneOutcome o;
  o.scene.name = e.name;
  o.scene.facts = {{"scene", e.scene}, {"reference", e.reference}};
  try {
    Scene scene = load_entry_scene(e);
    o.spp = a.spp > 0 ? a.spp : entry_spp(e, scene);
    o.scene.facts.push_back({"spp", std::to_string(o.spp)});
    const std::uint32_t seed = entry_seed(e, scene);
    o.scene.facts.push_back({"seed", std::to_string(seed)});
    RgbImage ref = read_rgb(e.reference), var = read_rgb(e.variance);
    std::string stem = (dir / e.name).string();
    std::string ref_png = stem + "_reference.png";
    write_preview_png(ref_png, ref);

    SceneRender cpu = render_scene(run_backend, "cpu", scene, o.spp, seed, a.threads);
    std::map<std::string, std::string> meta = {{"twinray:scene", e.scene}};
    write_result(cpu.result, output_paths(stem + "_cpu.exr"), meta, scene.film_half);
    o.scene.images.push_back({"CPU render", stem + "_cpu.png"});
    o.scene.facts.push_back(
        {"CPU", seconds_text(cpu.result.stats.seconds) + ", " + cpu.result.device});
    judge_against_reference(o, "cpu", scene, cpu, seed, e, ref, var, stem, a.threads);

    if (a.gpu != GpuMode::off) {
      try {
        SceneRender gpu = render_scene(run_backend, "gpu", scene, o.spp, seed, a.threads);
        write_result(gpu.result, output_paths(stem + "_gpu.exr"), meta, scene.film_half);
        o.scene.images.push_back({"GPU render", stem + "_gpu.png"});
        o.scene.facts.push_back(
            {"GPU", seconds_text(gpu.result.stats.seconds) + ", " + gpu.result.device});
        judge_against_reference(o, "gpu", scene, gpu, seed, e, ref, var, stem, a.threads);
        if (e.lockstep_spp == 0) {
          o.comparisons.push_back(between_backends(gpu, cpu, o.spp, stem + "_gpu_cpu"));
        } else {
          SceneRender gpu_ls =
              render_scene(run_backend, "gpu", scene, e.lockstep_spp, seed, a.threads);
          SceneRender cpu_ls =
              render_scene(run_backend, "cpu", scene, e.lockstep_spp, seed, a.threads);
          o.scene.facts.push_back({"lockstep spp", std::to_string(e.lockstep_spp)});
          o.comparisons.push_back(
              between_backends(gpu_ls, cpu_ls, e.lockstep_spp, stem + "_gpu_cpu"));
        }
      } catch (const BackendUnavailable& ex) {
        if (a.gpu == GpuMode::required) throw;
        o.scene.facts.push_back({"GPU", std::string("not available: ") + ex.what()});
      }
    }
    o.scene.images.push_back(
        {"Mitsuba reference (" + std::to_string(int(e.reference_spp)) + " spp)", ref_png});
    o.scene.passed = true;
    for (Comparison& c : o.comparisons) {
      o.scene.passed = o.scene.passed && (c.rejudged || c.shown.report.passed);
      o.scene.comparisons.push_back(c.shown);
    }
  } catch (const std::exception& ex) {
    o.scene.error = ex.what();
    o.scene.passed = false;
  }
  return o;
}

std::string summary_json(const std::string& suite, const std::vector<SceneOutcome>& outcomes,
                         bool passed) {
  JsonWriter j;
  j.begin_object().field("suite", suite).field("passed", passed).key("scenes").begin_array();
  for (const SceneOutcome& o : outcomes) {
    j.begin_object().field("name", o.scene.name).field("passed", o.scene.passed);
    if (!o.scene.error.empty()) j.field("error", o.scene.error);
    j.field("spp", int(o.spp)).key("comparisons").begin_array();
    for (const Comparison& c : o.comparisons)
      j.begin_object()
          .field("title", c.shown.title)
          .key("report")
          .raw(compare_report_json(c.shown.report, c.options))
          .end_object();
    j.end_array().end_object();
  }
  j.end_array().end_object();
  return j.str() + "\n";
}

}  // namespace

int validate_command(int argc, char** argv) {
  ValidateArgs a;
  try {
    a = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "twinray validate: %s\n(see twinray validate --help)\n", e.what());
    return kExitUsage;
  }
  if (a.help) {
    std::fputs(kUsage, stdout);
    return kExitOk;
  }
  std::vector<SuiteEntry> suite;
  try {
    suite = read_suite(a.suite);
    for (const std::string& name : a.only) find_entry(suite, name);
  } catch (const SuiteError& e) {
    std::fprintf(stderr, "twinray validate: %s\n", e.what());
    return kExitUsage;
  }
  try {
    create_output_folder(a.out);
    fs::path dir(a.out);
    std::vector<SceneOutcome> outcomes;
    bool passed = true;
    for (const SuiteEntry& e : suite) {
      if (!a.only.empty() && !a.only.count(e.name)) continue;
      SceneOutcome o = validate_scene(e, a, dir);
      std::printf("%s: %s\n", e.name.c_str(), o.scene.passed ? "PASS" : "FAIL");
      if (!o.scene.error.empty()) std::printf("  error: %s\n", o.scene.error.c_str());
      for (const Comparison& c : o.comparisons) print_comparison(c);
      std::fflush(stdout);
      passed = passed && o.scene.passed;
      outcomes.push_back(std::move(o));
    }
    std::vector<ReportScene> scenes;
    for (const SceneOutcome& o : outcomes) scenes.push_back(o.scene);
    std::string html = (dir / "report.html").string(), json = (dir / "summary.json").string();
    write_text_file(html, html_report("twinray validate " + a.suite, scenes));
    write_text_file(json, summary_json(a.suite, outcomes, passed));
    std::printf("validate: %s; wrote %s and %s\n", passed ? "PASS" : "FAIL", html.c_str(),
                json.c_str());
    return passed ? kExitOk : kExitFailed;
  } catch (...) {
    return report_failure("twinray validate");
  }
}

}  // namespace tr
