// Measurement tool (not a test): renders a scene on the GPU backend and prints the time of
// each phase and the throughput, for the specialized and the all-features pipeline.
//   gpu_bench SCENE.xml|SCENE.bin [--spp N] [--all-features | --all-features-but GROUPS]
//             [--without-bsdfs TYPES] [--without-samplers TYPES] [--keep-loops] [--device D]
//             [-D name=value]...
//             [--emitter-selection uniform|power|bvh] [--save DUMP.bin]
// --all-features-but bsdf,aov (say): every feature, but the scene's own BSDF types and AOVs —
// what one group of features costs the all-features pipeline. --without-bsdfs 10,11 (say) then
// drops BSDF types (core/scene_types.h's BSDF_* numbers) from the pipeline's, --without-samplers
// 5,6 sampler types (SAMPLER_* numbers). --keep-loops takes the shader's build for CPU devices
// (loops not unrolled) on a GPU too.
// Built without the loader (TWINRAY_BENCH_NO_LOADER), it reads only scene dumps
// (scene_dump.h), for machines that lack the loader's libraries; a dump keeps the emitter
// selection it was saved with.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu_backend/render_gpu.h"
#include "scene_dump.h"
#include "scenes/scene_features.h"
#ifndef TWINRAY_BENCH_NO_LOADER
#include "scenes/emitter_selection.h"
#include "scenes/load_scene.h"
#endif

namespace {

// The feature groups --all-features-but names, each a mask of SceneFeatures.
struct FeatureGroup {
  const char* name;
  uint32_t tr::SceneFeatures::*mask;
};
constexpr FeatureGroup kGroups[] = {
    {"bsdf", &tr::SceneFeatures::bsdf_types},
    {"emitter", &tr::SceneFeatures::emitter_types},
    {"shape", &tr::SceneFeatures::shape_types},
    {"texture", &tr::SceneFeatures::texture_types},
    {"material", &tr::SceneFeatures::material_flags},
    {"integrator", &tr::SceneFeatures::integrator_types},
    {"aov", &tr::SceneFeatures::aov_types},
    {"sampler", &tr::SceneFeatures::sampler_types},
    {"textured", &tr::SceneFeatures::textured_slots},
    {"selection", &tr::SceneFeatures::emitter_selections},
};

// The comma-separated items of `list`.
std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) items.push_back(item);
  return items;
}

// The type numbers of `list` (comma-separated, 0 to 31) as a mask; `option` names them in errors.
uint32_t type_mask(const std::string& list, const char* option) {
  uint32_t mask = 0;
  for (const std::string& t : split(list)) {
    if (t.empty() || t.size() > 2 || t.find_first_not_of("0123456789") != std::string::npos ||
        std::stoul(t) >= 32)
      throw std::runtime_error(std::string(option) + ": '" + t + "' is no type number (0 to 31)");
    mask |= 1u << std::stoul(t);
  }
  return mask;
}

// Every feature but the groups named in `groups`, which keep the scene's own, and without the
// BSDF and sampler types numbered in `without_bsdfs` and `without_samplers`
// (core/scene_types.h's BSDF_* and SAMPLER_*).
tr::SceneFeatures pipeline_features(const tr::SceneFeatures& own, const std::string& groups,
                                    const std::string& without_bsdfs,
                                    const std::string& without_samplers) {
  tr::SceneFeatures f = tr::all_features();
  for (const std::string& g : split(groups)) {
    const FeatureGroup* group = std::find_if(std::begin(kGroups), std::end(kGroups),
                                             [&](const FeatureGroup& k) { return g == k.name; });
    if (group == std::end(kGroups)) throw std::runtime_error("unknown feature group '" + g + "'");
    f.*group->mask = own.*group->mask;
  }
  f.bsdf_types &= ~type_mask(without_bsdfs, "--without-bsdfs");
  f.sampler_types &= ~type_mask(without_samplers, "--without-samplers");
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
  std::string without_samplers;
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
    } else if (a == "--without-samplers" && i + 1 < argc) {
      without_samplers = argv[++i];
    } else if (a == "--device" && i + 1 < argc) {
      options.device = argv[++i];
#ifndef TWINRAY_BENCH_NO_LOADER
    } else if (a == "--emitter-selection" && i + 1 < argc) {
      try {
        load.emitter_selection = tr::parse_emitter_selection(argv[++i]);
      } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "gpu_bench: --emitter-selection: %s\n", e.what());
        return 2;
      }
#endif
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
  if ((!without_bsdfs.empty() || !without_samplers.empty()) && !all) {
    std::fprintf(stderr,
                 "gpu_bench: --without-bsdfs and --without-samplers need --all-features or "
                 "--all-features-but\n");
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
    if (all)
      tuning.features = pipeline_features(tr::scene_features(scene.buffers), but, without_bsdfs,
                                          without_samplers);
    std::string pipeline = all ? "all-features" : "specialized";
    if (!but.empty()) pipeline += " but " + but;
    if (!without_bsdfs.empty()) pipeline += " without BSDFs " + without_bsdfs;
    if (!without_samplers.empty()) pipeline += " without samplers " + without_samplers;
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
        "dispatch %.2f Msamples/s, %.2f Mrays/s, %llu rejected | ray-generation stack %llu B\n",
        r.device.c_str(), r.width, r.height, r.spp, pipeline.c_str(), t.setup_seconds,
        t.pipeline_seconds, t.build_seconds, t.render_seconds, t.first_dispatch_spp,
        t.first_dispatch_seconds, double(r.stats.samples) / t.render_seconds * 1e-6,
        steady_seconds > 0.0 ? steady_samples / steady_seconds * 1e-6 : 0.0,
        double(r.stats.rays) / t.render_seconds * 1e-6,
        (unsigned long long)r.stats.rejected_nonfinite, (unsigned long long)t.raygen_stack_bytes);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_bench: %s\n", e.what());
    return 1;
  }
}
