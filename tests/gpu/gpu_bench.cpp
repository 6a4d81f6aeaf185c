// Measurement tool (not a test): renders a scene on the GPU backend and prints the time of
// each phase and the throughput, for the specialized and the all-features pipeline.
//   gpu_bench SCENE.xml|SCENE.bin [--spp N] [--all-features | --all-features-but GROUPS]
//             [--without-bsdfs TYPES] [--keep-loops] [--device D] [-D name=value]...
//             [--save DUMP.bin]
// --all-features-but bsdf,aov (say): every feature, but the scene's own BSDF types and AOVs —
// what one group of features costs the all-features pipeline. --without-bsdfs 10,11 (say) then
// drops BSDF types (core/scene_types.h's BSDF_* numbers) from the pipeline's. --keep-loops takes
// the shader's build for CPU devices (loops not unrolled) on a GPU too.
// Built without the loader (TWINRAY_BENCH_NO_LOADER), it reads only scene dumps
// (scene_dump.h), for machines that lack the loader's libraries.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gpu_backend/render_gpu.h"
#include "scene_dump.h"
#include "scenes/scene_features.h"
#ifndef TWINRAY_BENCH_NO_LOADER
#include "scenes/load_scene.h"
#endif

namespace {

// Every feature but the comma-separated groups of `groups`, which keep the scene's own.
tr::SceneFeatures all_features_but(const tr::SceneFeatures& own, const std::string& groups) {
  tr::SceneFeatures f = tr::all_features();
  std::stringstream list(groups);
  std::string g;
  while (std::getline(list, g, ',')) {
    if (g == "bsdf")
      f.bsdf_types = own.bsdf_types;
    else if (g == "emitter")
      f.emitter_types = own.emitter_types;
    else if (g == "shape")
      f.shape_types = own.shape_types;
    else if (g == "texture")
      f.texture_types = own.texture_types;
    else if (g == "material")
      f.material_flags = own.material_flags;
    else if (g == "integrator")
      f.integrator_types = own.integrator_types;
    else if (g == "aov")
      f.aov_types = own.aov_types;
    else if (g == "sampler")
      f.sampler_types = own.sampler_types;
    else if (g == "textured")
      f.textured_slots = own.textured_slots;
    else if (g == "selection")
      f.emitter_selections = own.emitter_selections;
    else
      throw std::runtime_error("unknown feature group '" + g + "'");
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: gpu_bench SCENE.xml [--spp N] [--all-features | --all-features-but "
                 "GROUPS] [--device D] [-D k=v]...\n");
    return 2;
  }
#ifndef TWINRAY_BENCH_NO_LOADER
  tr::LoadOptions load;
#endif
  tr::RenderOptions options;
  tr::GpuTuning tuning;
  std::string save;
  bool all = false;
  std::string but;
  std::string without_bsdfs;
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--spp" && i + 1 < argc) {
      options.spp = unsigned(std::stoul(argv[++i]));
    } else if (a == "--save" && i + 1 < argc) {
      save = argv[++i];
    } else if (a == "--all-features") {
      all = true;
    } else if (a == "--all-features-but" && i + 1 < argc) {
      all = true;
      but = argv[++i];
    } else if (a == "--keep-loops") {
      tuning.keep_loops = true;
    } else if (a == "--without-bsdfs" && i + 1 < argc) {
      without_bsdfs = argv[++i];
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
  if (!without_bsdfs.empty() && !all) {
    std::fprintf(stderr, "gpu_bench: --without-bsdfs needs --all-features or --all-features-but\n");
    return 2;
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
    if (all) {
      tuning.features = all_features_but(tr::scene_features(scene.buffers), but);
      std::stringstream list(without_bsdfs);
      std::string type;
      while (std::getline(list, type, ','))
        tuning.features->bsdf_types &= ~(1u << std::stoul(type));
    }
    std::string pipeline = all ? "all-features" : "specialized";
    if (!but.empty()) pipeline += " but " + but;
    if (!without_bsdfs.empty()) pipeline += " without BSDFs " + without_bsdfs;
    if (tuning.keep_loops) pipeline += ", loops kept";
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
        r.device.c_str(), r.width, r.height, r.spp, pipeline.c_str(), t.setup_seconds,
        t.pipeline_seconds, t.build_seconds, t.render_seconds, t.first_dispatch_spp,
        t.first_dispatch_seconds, double(r.stats.samples) / t.render_seconds * 1e-6,
        steady_seconds > 0.0 ? steady_samples / steady_seconds * 1e-6 : 0.0,
        double(r.stats.rays) / t.render_seconds * 1e-6,
        (unsigned long long)r.stats.rejected_nonfinite);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_bench: %s\n", e.what());
    return 1;
  }
}
