#include "app/render_command.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "app/progress_bar.h"
#include "app/render_passes.h"
#include "app/run_backend.h"
#include "app/stop_signals.h"
#include "io/image.h"
#include "io/temp_file.h"
#include "render/checkpoint.h"
#include "render/error_estimate.h"
#include "render/film_error.h"
#include "render/write_result.h"
#include "scenes/added_environment.h"
#include "scenes/emitter_selection.h"
#include "scenes/gltf/gltf_import.h"
#include "scenes/guide_aovs.h"
#include "scenes/load_scene.h"
#include "scenes/sampler.h"
#include "scenes/scene_digest.h"

namespace tr {
namespace {

const char* kUsage =
    "usage: twinray render SCENE [-o OUT.exr] [-D NAME=VALUE]... [-a PATH]... [--spp N]\n"
    "                      [--seed S] [--threads N] [--backend cpu|gpu] [--device N|NAME]\n"
    "                      [--randomizations K] [--aov LIST] [--emitter-selection S]\n"
    "                      [--envmap FILE [--envmap-scale S] | --constant RGB] [--camera C]\n"
    "                      [--strict-gltf]\n"
    "  Renders a Mitsuba 3 XML, .scn or glTF 2.0 (.gltf/.glb) scene (-D width, height, spp,\n"
    "  max_depth; scenes/README.md). Writes OUT.exr (mean radiance, RGB in the film's\n"
    "  component_format: float16 unless the scene asks for float32, as Mitsuba),\n"
    "  OUT_var.exr (per-sample variance v: v / spp estimates the variance of a pixel) and\n"
    "  OUT.png (sRGB preview); OUT defaults to the scene's file name in the current directory.\n"
    "  -D NAME=VALUE   override a <default> of the scene      -a PATH  add a search path\n"
    "  --spp N         samples per pixel (default: the scene's sampler sample_count), rounded\n"
    "                  as the scene's sampler rounds sample_count\n"
    "  --randomizations K  render K independent randomizations (passes) of the scene's\n"
    "                  correlated sampler, each of ceil(spp / K) samples rounded as the sampler\n"
    "                  rounds sample_count (spp becomes K times that); with K >= 2 the variance\n"
    "                  output estimates the error from the passes (K >= 16 for --target-error).\n"
    "                  independent: accepted, changes nothing. Default: one pass\n"
    "  --aov LIST      also write denoiser guide buffers: the scene's integrator is wrapped in\n"
    "                  Mitsuba's aov integrator (scenes/guide_aovs.h), its colour stays R, G, B;\n"
    "                  LIST is comma-separated TYPE or NAME:TYPE (channels NAME.R/G/B, .X/Y/Z,\n"
    "                  .T, .U/V or .I), e.g. albedo,sh_normal,depth. Types: albedo, depth,\n"
    "                  position, uv, geo_normal, sh_normal, prim_index, shape_index. Refused\n"
    "                  when the scene's integrator is already aov or moment; --resume needs\n"
    "                  the same types\n"
    "  --emitter-selection S  how a light sample chooses its emitter: uniform (Mitsuba's: by\n"
    "                  sampling_weight, the default), power (by estimated power times\n"
    "                  sampling_weight) or bvh (a light BVH by power, distance and\n"
    "                  orientation from the shading point; scenes/emitter_selection.h). All\n"
    "                  unbiased; they change the noise, hence the variance output\n"
    "  --envmap FILE   light the scene with Mitsuba's envmap emitter of this image (EXR, HDR,\n"
    "                  ...; +y up), scaled by --envmap-scale S (default 1)\n"
    "  --constant RGB  light it with Mitsuba's constant emitter of radiance V or R,G,B\n"
    "                  (either refused when the scene has a constant or envmap emitter)\n"
    "  --camera C      glTF only: N renders through the file's cameras[N]; auto frames the\n"
    "                  scene's bounds (yfov 45 degrees, looking down -z; the default when no\n"
    "                  node has a camera)\n"
    "  --strict-gltf   glTF only: refuse the scene (exit 3) where a field does not map\n"
    "                  exactly, instead of warning (scenes/README.md, glTF 2.0 scenes)\n"
    "  --seed S        random seed (default: the scene's sampler seed, 0 if it sets none);\n"
    "                  same seed => same image on any thread count\n"
    "  --threads N     CPU worker threads (default: all cores)\n"
    "  --backend B     cpu (the reference, default) or gpu (Vulkan ray tracing)\n"
    "  --device D      GPU device index or name substring (see `twinray devices`)\n"
    "  Budgets (the render stops at the first one reached; --spp stays the cap):\n"
    "  --time SECONDS          stop after this much rendering time\n"
    "  --target-error E        stop when the estimated relative error (the root of the\n"
    "                          expected relMSE, render/film_error.h) is at most E\n"
    "  --checkpoint SECONDS    every SECONDS, and at the end, write OUT.checkpoint atomically\n"
    "  --resume FILE           continue the render a checkpoint holds (same scene, defines,\n"
    "                          seed, backend and twinray build; refused otherwise)\n"
    "  SIGINT/SIGTERM finish the pass in flight, write the outputs (and the checkpoint) with\n"
    "  the samples rendered so far and exit with status 7.\n";

struct RenderArgs {
  std::string scene;
  std::string output;
  LoadOptions load;
  RenderOptions render;
  std::optional<std::uint32_t> seed;  // unset: the scene's sampler `seed`
  std::string backend = "cpu";
  RenderBudget budget;
  double checkpoint_seconds = 0.0;  // 0: no checkpoints
  std::string resume;
  std::uint32_t randomizations = 0;    // 0: not asked for (one pass, Mitsuba semantics)
  std::vector<std::string> aov_lists;  // each --aov's LIST
};

double positive_number(const std::string& option, const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !(v > 0.0) || !std::isfinite(v))
    throw UsageError(option + " expects a positive number, got '" + value + "'");
  return v;
}

bool is_camera_choice(const std::string& c) {
  return c == "auto" ||
         (!c.empty() && c.size() < 10 && c.find_first_not_of("0123456789") == std::string::npos);
}

void check_environment(const AddedEnvironment& e, bool scale_given) {
  if (!e.envmap.empty() && e.constant)
    throw UsageError("--envmap and --constant together: Mitsuba holds one environment a scene");
  if (scale_given && e.envmap.empty()) throw UsageError("--envmap-scale needs --envmap");
  std::error_code ec;
  if (!e.envmap.empty() && !std::filesystem::is_regular_file(e.envmap, ec))
    throw UsageError("--envmap: '" + e.envmap + "' is not a file");
}

RenderArgs parse(int argc, char** argv) {
  RenderArgs a;
  bool envmap_scale = false;
  Arguments args(argc, argv);
  while (args.more()) {
    std::string arg = args.next();
    if (arg == "-o") {
      a.output = args.value(arg);
    } else if (arg == "-D") {
      auto [name, value] = args.name_value(arg);
      a.load.defines[name] = value;
    } else if (arg == "-a") {
      a.load.search_paths.push_back(args.value(arg));
    } else if (arg == "--spp") {
      a.render.spp = args.uint_value(arg, 1);
    } else if (arg == "--seed") {
      a.seed = args.uint_value(arg, 0);
    } else if (arg == "--threads") {
      a.render.threads = args.uint_value(arg, 1);
    } else if (arg == "--backend") {
      a.backend = args.value(arg);
      if (a.backend != "cpu" && a.backend != "gpu")
        throw UsageError("--backend must be cpu or gpu, got '" + a.backend + "'");
    } else if (arg == "--device") {
      a.render.device = args.value(arg);
    } else if (arg == "--time") {
      a.budget.seconds = positive_number(arg, args.value(arg));
    } else if (arg == "--target-error") {
      a.budget.error = positive_number(arg, args.value(arg));
    } else if (arg == "--checkpoint") {
      a.checkpoint_seconds = positive_number(arg, args.value(arg));
    } else if (arg == "--randomizations") {
      a.randomizations = args.uint_value(arg, 1);
    } else if (arg == "--resume") {
      a.resume = args.value(arg);
    } else if (arg == "--emitter-selection") {
      try {
        a.load.emitter_selection = parse_emitter_selection(args.value(arg));
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--emitter-selection: ") + e.what());
      }
    } else if (arg == "--envmap") {
      a.load.environment.envmap = args.value(arg);
    } else if (arg == "--envmap-scale") {
      a.load.environment.envmap_scale = positive_number(arg, args.value(arg));
      envmap_scale = true;
    } else if (arg == "--constant") {
      try {
        a.load.environment.constant = parse_radiance(args.value(arg));
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--constant: ") + e.what());
      }
    } else if (arg == "--camera") {
      a.load.camera = args.value(arg);
      if (!is_camera_choice(a.load.camera))
        throw UsageError("--camera expects auto or a camera index, got '" + a.load.camera + "'");
    } else if (arg == "--strict-gltf") {
      a.load.strict_gltf = true;
    } else if (arg == "--aov") {
      a.aov_lists.push_back(args.value(arg));
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.scene.empty()) {
      a.scene = arg;
    } else {
      throw UsageError("more than one scene given ('" + a.scene + "', '" + arg + "')");
    }
  }
  if (a.scene.empty()) throw UsageError("no scene file given");
  check_environment(a.load.environment, envmap_scale);
  if ((!a.load.camera.empty() || a.load.strict_gltf) && !is_gltf(a.scene))
    throw UsageError(std::string(a.load.strict_gltf ? "--strict-gltf" : "--camera") +
                     " is for glTF scenes; '" + a.scene + "' is not a .gltf or .glb file");
  if (!a.aov_lists.empty()) {
    std::string joined;  // several --aov options add up
    for (const std::string& list : a.aov_lists) joined += (joined.empty() ? "" : ",") + list;
    try {
      a.load.guide_aovs = parse_guide_aovs(joined);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--aov: ") + e.what());
    }
  }
  if (a.output.empty()) a.output = std::filesystem::path(a.scene).stem().string() + ".exr";
  return a;
}

// Fails before rendering when the outputs could not be written afterwards.
void check_output_directory(const std::string& path) {
  std::filesystem::path dir = std::filesystem::absolute(path).parent_path();
  if (!std::filesystem::is_directory(dir))
    throw ImageError(path + ": output directory " + dir.string() + " does not exist");
  if (access(dir.c_str(), W_OK) != 0)
    throw ImageError(path + ": output directory " + dir.string() + " is not writable");
  TempFile probe(path);  // what access() cannot tell (e.g. for root): whether files can be made
}

// --randomizations K: the scene's correlated sampler in K passes of ceil(spp / K) samples,
// rounded as the sampler rounds sample_count (scenes/sampler.h); spp becomes K times the pass.
// Returns false (a usage error, printed) when the pass or the total is out of range.
bool set_randomizations(Scene& scene, std::uint32_t k, std::uint32_t& spp) {
  try {
    set_sample_count_in_passes(scene, spp ? spp : scene.spp, k);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "twinray render: --randomizations %u: %s\n", k, e.what());
    return false;
  }
  spp = scene.spp;
  return true;
}

void print_summary(const RenderResult& r, const OutputPaths& paths, const PassOutcome& outcome,
                   const std::string& sample_count_note) {
  const RenderStats& s = r.stats;
  double sps = s.seconds > 0 ? double(s.samples) / s.seconds : 0.0;
  double rps = s.seconds > 0 ? double(s.rays) / s.seconds : 0.0;
  std::printf(
      "twinray: %ux%u, %u spp, %.3f s, %.3f Msamples/s, %.3f Mrays/s, %llu NaN/Inf samples "
      "rejected\n",
      r.width, r.height, r.spp, s.seconds, sps * 1e-6, rps * 1e-6,
      static_cast<unsigned long long>(s.rejected_nonfinite));
  if (std::isfinite(outcome.error))
    std::printf("twinray: stopped: %s; estimated relative error %.4g\n",
                stop_reason_name(outcome.stop), outcome.error);
  else if (r.pass_size > 0)
    std::printf("twinray: stopped: %s; relative error not estimated below %u passes (%u done)\n",
                stop_reason_name(outcome.stop), kMinErrorPasses,
                completed_passes(r.pass_size, r.spp));
  else
    std::printf("twinray: stopped: %s; relative error not estimated below %u spp\n",
                stop_reason_name(outcome.stop), kMinErrorSamples);
  std::printf("twinray: backend %s (%s); wrote %s, %s, %s\n", r.backend.c_str(), r.device.c_str(),
              paths.image.c_str(), paths.variance.c_str(), paths.preview.c_str());
  if (!sample_count_note.empty()) std::printf("twinray: %s\n", sample_count_note.c_str());
  if (r.pass_size > 0)
    std::printf("twinray: variance output: %s\n",
                variance_estimate_name(r.pass_size, r.spp).c_str());
}

// A correlated sampler's variance output that rests on fewer than 2 passes is the per-sample
// variance, no estimate of its error: one line on stderr says so and names the fix.
void warn_without_passes(const RenderResult& r, const std::string& sampler) {
  if (r.pass_size == 0 || variance_from_passes(r.pass_size, r.spp)) return;
  std::fprintf(stderr,
               "twinray: warning: %s's samples are correlated and the variance output rests on "
               "%u complete pass(es): it is their per-sample variance, not an error estimate; "
               "render with --randomizations K (K >= 2) for one\n",
               sampler.c_str(), completed_passes(r.pass_size, r.spp));
}

}  // namespace

int render_command(int argc, char** argv) {
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::fputs(kUsage, stdout);
      return kExitOk;
    }
  }
  RenderArgs a;
  try {
    a = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "twinray render: %s\n%s", e.what(), kUsage);
    return kExitUsage;
  }
  try {
    OutputPaths paths = output_paths(a.output);
    check_output_directory(paths.image);
    Scene scene = load_scene(a.scene, a.load);
    if (a.render.spp && a.randomizations == 0) {
      try {
        set_sample_count(scene, a.render.spp);
      } catch (const SceneError& e) {
        std::fprintf(stderr, "twinray render: --spp %u: %s\n", a.render.spp, e.what());
        return kExitUsage;
      }
      a.render.spp = scene.spp;
    }
    if (a.randomizations > 0 && !set_randomizations(scene, a.randomizations, a.render.spp))
      return kExitUsage;
    a.render.seed = a.seed.value_or(scene.seed);
    const Camera& camera = scene.buffers.globals.camera;
    a.budget.spp = a.render.spp ? a.render.spp : scene.spp;
    std::unique_ptr<Renderer> renderer = make_renderer(a.backend, scene, a.render);
    RenderIdentity id{build_id(),    scene_digest(scene),     a.backend,
                      a.render.seed, renderer->granularity(), camera.width,
                      camera.height};
    id.aov_count = scene.buffers.globals.integrator.aov_count;
    id.pass_size = renderer->pass_size();
    FilmState film = a.resume.empty()
                         ? empty_film(camera.width, camera.height, id.aov_count, id.pass_size)
                         : read_checkpoint(a.resume, id);
    if (film.samples > a.budget.spp)
      throw CheckpointError(a.resume + ": holds " + std::to_string(film.samples) +
                            " spp, more than the " + std::to_string(a.budget.spp) + " asked for");
    const std::string checkpoint =
        paths.image.substr(0, paths.image.size() - std::string(".exr").size()) + ".checkpoint";
    ProgressBar bar;
    StopSignals signals;
    PassOutcome outcome = render_passes(
        *renderer, film, a.budget, a.checkpoint_seconds,
        [&](const FilmState& f) { write_checkpoint(checkpoint, id, f); },
        [&bar](std::uint64_t done, std::uint64_t total) { bar.update(done, total); },
        [&signals] { return signals.raised(); });
    bar.finish();
    const RenderResult result = film_result_header(film, *renderer);
    const std::string sampler = sampler_name(scene.buffers.globals.sampler_params.type);
    std::map<std::string, std::string> metadata = {
        {"twinray:scene", a.scene},
        {"twinray:integrator", scene.integrator_name},
        {"twinray:sampler", sampler},
        {"twinray:emitter_selection",
         emitter_selection_name(scene.buffers.globals.emitter_selection)},
        {"twinray:version", TWINRAY_VERSION},
        {"twinray:stopped", stop_reason_name(outcome.stop)},
        {"twinray:estimated_error", std::to_string(outcome.error)}};
    if (!scene.sample_count_note.empty())
      metadata["twinray:sample_count_rounding"] = scene.sample_count_note;
    write_film(film, result, paths, metadata, scene.film_half, scene.aov_channels);
    print_summary(result, paths, outcome, scene.sample_count_note);
    if (a.randomizations > 0 && result.pass_size > 0)
      std::printf("twinray: --randomizations %u: %u independent passes of %u samples (%s)\n",
                  a.randomizations, a.randomizations, result.pass_size, sampler.c_str());
    warn_without_passes(result, sampler);
    return outcome.stop == StopReason::Interrupted ? kExitInterrupted : kExitOk;
  } catch (...) {
    return report_failure("twinray");
  }
}

}  // namespace tr
