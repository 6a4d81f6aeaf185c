#include "app/converge_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "app/run_backend.h"
#include "io/temp_file.h"
#include "scenes/load_scene.h"
#include "scenes/sampler.h"
#include "validation/harness/scene_render.h"
#include "validation/harness/variant.h"
#include "validation/image/convergence.h"
#include "validation/image/error_calibration.h"
#include "validation/image/metrics.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

const char* kUsage =
    R"(usage: twinray converge SCENE.xml --reference REF.exr --budget SECONDS [options]

For each variant, renders SCENE at start-spp, 2 start-spp, 4 start-spp, ... (--repeats fresh
renders a rung, seeds seed, seed+1, ..., the sampler's sample_count set to the rung's spp and
rounded as the sampler rounds it, or to spp / K with randomizations=K) until the variant's time budget is spent or the next rung
would overrun it (its time predicted as twice the last), and records each rung's mean render
time, RMSE and relMSE against REF (validation/image/metrics.h) and the standard error of the
mean relMSE; with repeats, also the relMSE observed among the rung's renders and the one
their own variance outputs estimate (validation/image/error_calibration.h): whether the error
estimate is honest. Writes OUT/convergence.csv,
OUT/convergence.svg (log-log RMSE and relMSE against seconds) and OUT/time_to_error.csv, and
prints the time to reach each relMSE target and the fitted convergence rate.

Options:
  --variant SPEC     a render variant, comma-separated KEY=VALUE (may repeat; default: the
                     scene as written, on the CPU):
                       integrator=path|direct  max_depth=N (-1 unbounded)  rr_depth=N|off
                       sampler=NAME   randomizations=K   backend=cpu|gpu  label=TEXT
                       emitter_selection=uniform|power|bvh
                     e.g. --variant max_depth=3 --variant rr_depth=off,label=no-RR
  --budget SECONDS   time budget of each variant (required)
  --start-spp N      first rung of the spp ladder (default 1)
  --max-spp N        last rung at most (default 1048576)
  --seed S           seed of the first render (default: the scene's sampler seed)
  --repeats N        renders a rung, with distinct seeds, for error bars (default 1)
  --targets LIST     comma-separated relMSE levels for time-to-error (default 1e-2,1e-3,1e-4)
  --out DIR          output folder (default: converge-<scene name>)
  --threads N        CPU worker threads (default: all cores)
  -D NAME=VALUE      override a <default> of the scene     -a PATH  add a search path

Exit status: 0 ok, 2 usage error, 3 invalid scene, 4 backend unavailable, 5 an output could
not be written, 6 internal error.
)";

struct ConvergeArgs {
  std::string scene, reference, out;
  std::vector<RenderVariant> variants;
  double budget = 0.0;
  std::uint32_t start_spp = 1, max_spp = 1u << 20, threads = 0, repeats = 1;
  std::optional<std::uint32_t> seed;  // unset: the scene's sampler `seed`
  std::vector<double> targets = {1e-2, 1e-3, 1e-4};
  LoadOptions load;
  bool help = false;
};

double parse_positive(const std::string& name, const std::string& v) {
  size_t used = 0;
  double x = 0.0;
  try {
    x = std::stod(v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (v.empty() || used != v.size() || !(x > 0.0) || !std::isfinite(x))
    throw UsageError(name + " expects a positive number, got '" + v + "'");
  return x;
}

ConvergeArgs parse(int argc, char** argv) {
  ConvergeArgs a;
  Arguments args(argc - 1, argv + 1);
  while (args.more()) {
    std::string arg = args.next();
    if (arg == "--help" || arg == "-h") {
      a.help = true;
    } else if (arg == "--reference") {
      a.reference = args.value(arg);
    } else if (arg == "--budget") {
      a.budget = parse_positive(arg, args.value(arg));
    } else if (arg == "--variant") {
      try {
        a.variants.push_back(parse_variant(args.value(arg)));
      } catch (const VariantError& e) {
        throw UsageError(std::string("--variant: ") + e.what());
      }
    } else if (arg == "--start-spp") {
      a.start_spp = args.uint_value(arg, 1);
    } else if (arg == "--max-spp") {
      a.max_spp = args.uint_value(arg, 1);
    } else if (arg == "--seed") {
      a.seed = args.uint_value(arg, 0);
    } else if (arg == "--repeats") {
      a.repeats = args.uint_value(arg, 1);
    } else if (arg == "--targets") {
      a.targets.clear();
      std::istringstream list(args.value(arg));
      std::string t;
      while (std::getline(list, t, ',')) a.targets.push_back(parse_positive("--targets", t));
      if (a.targets.empty()) throw UsageError("--targets lists no level");
    } else if (arg == "--out") {
      a.out = args.value(arg);
    } else if (arg == "--threads") {
      a.threads = args.uint_value(arg, 1);
    } else if (arg == "-D") {
      auto [name, value] = args.name_value(arg);
      a.load.defines[name] = value;
    } else if (arg == "-a") {
      a.load.search_paths.push_back(args.value(arg));
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.scene.empty()) {
      a.scene = arg;
    } else {
      throw UsageError("more than one scene given ('" + a.scene + "', '" + arg + "')");
    }
  }
  if (a.help) return a;
  if (a.scene.empty()) throw UsageError("no scene file given");
  if (a.reference.empty()) throw UsageError("--reference is required");
  if (a.budget <= 0.0) throw UsageError("--budget is required");
  if (a.start_spp > a.max_spp) throw UsageError("--start-spp exceeds --max-spp");
  if (a.variants.empty()) a.variants.push_back(parse_variant(""));
  if (a.out.empty()) a.out = "converge-" + fs::path(a.scene).stem().string();
  return a;
}

ConvergenceSeries converge_variant(const Scene& base, const RenderVariant& v,
                                   const RgbImage& reference, const ConvergeArgs& a) {
  Scene scene = apply_variant(base, v);
  ConvergenceSeries series;
  series.name = v.label + " (" + v.backend + ")";
  double spent = 0.0, last = 0.0;
  std::uint32_t seed = a.seed.value_or(base.seed);
  for (std::uint64_t spp = a.start_spp; spp <= a.max_spp; spp *= 2) {
    if (!series.points.empty() && spent + 2.0 * last > a.budget) break;
    Scene rung = scene;
    set_variant_sample_count(rung, v, std::uint32_t(spp));
    ConvergencePoint p;
    p.spp = double(rung.spp);
    p.renders = int(a.repeats);
    double rung_seconds = 0.0, relmse_squares = 0.0;
    std::vector<RgbImage> means, variances;
    for (std::uint32_t k = 0; k < a.repeats; ++k, ++seed) {
      SceneRender r = render_scene(run_backend, v.backend, rung, rung.spp, seed, a.threads);
      check_same_size(r.mean, "render", reference, a.reference);
      ErrorMetrics m = error_metrics(r.mean, reference);
      if (a.repeats > 1) {
        means.push_back(r.mean);
        variances.push_back(r.variance);
      }
      rung_seconds += r.result.stats.seconds;
      p.rmse += m.rmse / a.repeats;
      p.relmse += m.relmse / a.repeats;
      relmse_squares += m.relmse * m.relmse;
    }
    p.seconds = rung_seconds / a.repeats;
    if (a.repeats > 1) {
      p.relmse_stderr = std::sqrt(std::max(0.0, relmse_squares - a.repeats * p.relmse * p.relmse) /
                                  (double(a.repeats - 1) * a.repeats));
      ErrorCalibration c = error_calibration(means, variances, p.spp, reference);
      p.estimated_relmse = c.estimated;
      p.seed_relmse = c.observed;
    }
    series.points.push_back(p);
    std::printf("  %-28s %8u spp  %9.3f s  RMSE %.5g  relMSE %.5g", series.name.c_str(), rung.spp,
                p.seconds, p.rmse, p.relmse);
    if (a.repeats > 1)
      std::printf(" +- %.2g (%u renders); among them %.5g, their estimate %.5g (x%.3f)",
                  p.relmse_stderr, a.repeats, p.seed_relmse, p.estimated_relmse,
                  p.estimated_relmse / p.seed_relmse);
    std::printf("\n");
    std::fflush(stdout);
    last = rung_seconds;
    spent += rung_seconds;
  }
  return series;
}

std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// Columns: series,metric,target,seconds (seconds empty when the series never got there).
std::string time_to_error_csv(const std::vector<ConvergenceSeries>& all,
                              const std::vector<double>& targets) {
  std::string csv = "series,metric,target,seconds\n";
  char buf[128];
  for (const ConvergenceSeries& s : all)
    for (double t : targets) {
      std::optional<double> sec = time_to_error(s, ConvergenceMetric::relmse, t);
      std::snprintf(buf, sizeof buf, ",relmse,%.6g,", t);
      csv += csv_quote(s.name) + buf;
      if (sec) {
        std::snprintf(buf, sizeof buf, "%.6g", *sec);
        csv += buf;
      }
      csv += "\n";
    }
  return csv;
}

void print_summary(const std::vector<ConvergenceSeries>& all, const std::vector<double>& targets) {
  for (const ConvergenceSeries& s : all) {
    std::printf("%s:", s.name.c_str());
    for (double t : targets) {
      std::optional<double> sec = time_to_error(s, ConvergenceMetric::relmse, t);
      if (sec)
        std::printf("  relMSE %.0e in %.3g s", t, *sec);
      else
        std::printf("  relMSE %.0e not reached", t);
    }
    std::optional<double> rate = convergence_rate(s, ConvergenceMetric::relmse);
    if (rate) std::printf("  (relMSE ~ seconds^%.2f)", *rate);
    std::printf("\n");
  }
}

}  // namespace

int converge_command(int argc, char** argv) {
  ConvergeArgs a;
  try {
    a = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "twinray converge: %s\n(see twinray converge --help)\n", e.what());
    return kExitUsage;
  }
  if (a.help) {
    std::fputs(kUsage, stdout);
    return kExitOk;
  }
  RgbImage reference;
  try {
    reference = read_rgb(a.reference);
  } catch (const ImageError& e) {
    std::fprintf(stderr, "twinray converge: %s\n", e.what());
    return kExitUsage;
  }
  try {
    create_output_folder(a.out);
    fs::path dir(a.out);
    Scene scene = load_scene(a.scene, a.load);
    std::vector<ConvergenceSeries> all;
    for (const RenderVariant& v : a.variants)
      all.push_back(converge_variant(scene, v, reference, a));
    std::string csv = (dir / "convergence.csv").string(), svg = (dir / "convergence.svg").string(),
                tte = (dir / "time_to_error.csv").string();
    write_text_file(csv, convergence_csv(all));
    write_text_file(svg, convergence_svg(all, "twinray converge " + a.scene));
    write_text_file(tte, time_to_error_csv(all, a.targets));
    print_summary(all, a.targets);
    std::printf("converge: wrote %s, %s, %s\n", csv.c_str(), svg.c_str(), tte.c_str());
    return kExitOk;
  } catch (...) {
    return report_failure("twinray converge");
  }
}

}  // namespace tr
