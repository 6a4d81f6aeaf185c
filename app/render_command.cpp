#include "app/render_command.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "app/progress_bar.h"
#include "app/run_backend.h"
#include "io/image.h"
#include "render/write_result.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

const char* kUsage =
    "usage: twinray render SCENE.xml [-o OUT.exr] [-D NAME=VALUE]... [-a PATH]... [--spp N]\n"
    "                      [--seed S] [--threads N] [--backend cpu|gpu] [--device N|NAME]\n"
    "  Renders a Mitsuba 3 XML scene. Writes OUT.exr (mean radiance, RGB in the film's\n"
    "  component_format: float16 unless the scene asks for float32, as Mitsuba),\n"
    "  OUT_var.exr (per-sample variance) and OUT.png (sRGB preview); OUT defaults to the\n"
    "  scene's file name in the current directory.\n"
    "  -D NAME=VALUE   override a <default> of the scene      -a PATH  add a search path\n"
    "  --spp N         samples per pixel (default: the scene's sampler sample_count)\n"
    "  --seed S        random seed (default: the scene's sampler seed, 0 if it sets none);\n"
    "                  same seed => same image on any thread count\n"
    "  --threads N     CPU worker threads (default: all cores)\n"
    "  --backend B     cpu (the reference, default) or gpu (Vulkan ray tracing)\n"
    "  --device D      GPU device index or name substring (see `twinray devices`)\n";

struct RenderArgs {
  std::string scene;
  std::string output;
  LoadOptions load;
  RenderOptions render;
  std::optional<std::uint32_t> seed;  // unset: the scene's sampler `seed`
  std::string backend = "cpu";
};

RenderArgs parse(int argc, char** argv) {
  RenderArgs a;
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
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.scene.empty()) {
      a.scene = arg;
    } else {
      throw UsageError("more than one scene given ('" + a.scene + "', '" + arg + "')");
    }
  }
  if (a.scene.empty()) throw UsageError("no scene file given");
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
}

void print_summary(const RenderResult& r, const OutputPaths& paths) {
  const RenderStats& s = r.stats;
  double sps = s.seconds > 0 ? double(s.samples) / s.seconds : 0.0;
  double rps = s.seconds > 0 ? double(s.rays) / s.seconds : 0.0;
  std::printf(
      "twinray: %ux%u, %u spp, %.3f s, %.3f Msamples/s, %.3f Mrays/s, %llu NaN/Inf samples "
      "rejected\n",
      r.width, r.height, r.spp, s.seconds, sps * 1e-6, rps * 1e-6,
      static_cast<unsigned long long>(s.rejected_nonfinite));
  std::printf("twinray: backend %s (%s); wrote %s, %s, %s\n", r.backend.c_str(), r.device.c_str(),
              paths.image.c_str(), paths.variance.c_str(), paths.preview.c_str());
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
    a.render.seed = a.seed.value_or(scene.seed);
    ProgressBar bar;
    a.render.progress = [&bar](std::uint64_t done, std::uint64_t total) {
      bar.update(done, total);
    };
    RenderResult result = run_backend(a.backend, scene, a.render);
    bar.finish();
    write_result(result, paths,
                 {{"twinray:scene", a.scene},
                  {"twinray:integrator", scene.integrator_name},
                  {"twinray:version", TWINRAY_VERSION}},
                 scene.film_half);
    print_summary(result, paths);
    return kExitOk;
  } catch (...) {
    return report_failure("twinray");
  }
}

}  // namespace tr
