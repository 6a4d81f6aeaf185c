// Measurement tool (not a test): renders a scene on the GPU backend and prints the time of
// each phase and the throughput, for the specialized and the all-features pipeline.
//   gpu_bench SCENE.xml|SCENE.bin [--spp N] [--all-features] [--device D] [-D name=value]...
//             [--save DUMP.bin]
// Built without the loader (TWINRAY_BENCH_NO_LOADER), it reads only scene dumps
// (scene_dump.h), for machines that lack the loader's libraries.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include "gpu_backend/render_gpu.h"
#include "scene_dump.h"
#ifndef TWINRAY_BENCH_NO_LOADER
#include "scenes/load_scene.h"
#endif

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(
        stderr, "usage: gpu_bench SCENE.xml [--spp N] [--all-features] [--device D] [-D k=v]...\n");
    return 2;
  }
#ifndef TWINRAY_BENCH_NO_LOADER
  tr::LoadOptions load;
#endif
  tr::RenderOptions options;
  tr::GpuTuning tuning;
  std::string save;
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--spp" && i + 1 < argc) {
      options.spp = unsigned(std::stoul(argv[++i]));
    } else if (a == "--save" && i + 1 < argc) {
      save = argv[++i];
    } else if (a == "--all-features") {
      tuning.specialize = false;
    } else if (a == "--device" && i + 1 < argc) {
      options.device = argv[++i];
    } else if (a == "-D" && i + 1 < argc) {
      std::string kv = argv[++i];
#ifndef TWINRAY_BENCH_NO_LOADER
      size_t eq = kv.find('=');
      load.defines[kv.substr(0, eq)] = eq == std::string::npos ? "" : kv.substr(eq + 1);
#endif
    } else {
      std::fprintf(stderr, "gpu_bench: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  try {
    const std::string path = argv[1];
    const bool dump = path.size() > 4 && path.compare(path.size() - 4, 4, ".bin") == 0;
#ifdef TWINRAY_BENCH_NO_LOADER
    if (!dump) throw std::runtime_error("this gpu_bench reads only scene dumps (.bin)");
    tr::Scene scene = tr::test::load_scene_dump(path);
#else
    tr::Scene scene = dump ? tr::test::load_scene_dump(path) : tr::load_scene(path, load);
#endif
    if (!save.empty()) {
      tr::test::save_scene_dump(scene, save);
      return 0;
    }
    tr::GpuTimings t;
    tr::RenderResult r = tr::render_with_raygen(scene, options, tr::renderer_raygen(), tuning, &t);
    // Throughput over all dispatches, and after the first one, which may include the
    // driver's shader compilation (lavapipe compiles there).
    const double pixels = double(r.width) * r.height;
    const double steady_seconds = t.render_seconds - t.first_dispatch_seconds;
    const double steady_samples = double(r.spp - t.first_dispatch_spp) * pixels;
    std::printf(
        "%s | %ux%u, %u spp, %s pipeline | setup %.3f s, pipeline %.3f s, AS build %.3f s, "
        "render %.3f s (first dispatch, %u spp: %.3f s) | %.2f Msamples/s, after the first "
        "dispatch %.2f Msamples/s, %.2f Mrays/s, %llu rejected\n",
        r.device.c_str(), r.width, r.height, r.spp,
        tuning.specialize ? "specialized" : "all-features", t.setup_seconds, t.pipeline_seconds,
        t.build_seconds, t.render_seconds, t.first_dispatch_spp, t.first_dispatch_seconds,
        double(r.stats.samples) / t.render_seconds * 1e-6,
        steady_seconds > 0.0 ? steady_samples / steady_seconds * 1e-6 : 0.0,
        double(r.stats.rays) / t.render_seconds * 1e-6,
        (unsigned long long)r.stats.rejected_nonfinite);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_bench: %s\n", e.what());
    return 1;
  }
}
