#include "validation/harness/conformance.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>

#include "scenes/load_scene.h"
#include "scenes/plugins.h"
#include "validation/harness/scene_render.h"

namespace tr {

namespace fs = std::filesystem;

std::vector<std::string> conformance_scenes(const std::string& folder) {
  std::vector<std::string> scenes;
  for (const fs::directory_entry& e : fs::directory_iterator(folder))
    if (e.is_regular_file() && e.path().extension() == ".xml") scenes.push_back(e.path().string());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

ConformanceResult check_conformance(const std::string& scene_path,
                                    const ConformanceOptions& options) {
  ConformanceResult r;
  r.scene = scene_path;
  auto start = std::chrono::steady_clock::now();
  try {
    // As Mitsuba's documentation script: spp is passed to every scene, used where it asks.
    LoadOptions load;
    load.defines["spp"] = std::to_string(options.spp);
    load.unused_defines_allowed = true;
    load.search_paths = options.search_paths;
    Scene scene = load_scene(scene_path, load);
    SceneRender render = render_scene(options.render, options.backend, scene, options.spp,
                                      scene.seed, options.threads);
    if (!options.preview_dir.empty())
      write_preview_png(
          (fs::path(options.preview_dir) / (fs::path(scene_path).stem().string() + ".png"))
              .string(),
          render.mean);
    r.outcome = ConformanceOutcome::Rendered;
  } catch (const UnsupportedPluginError& e) {
    r.outcome = e.support == PluginSupport::OutOfScope ? ConformanceOutcome::OutOfScope
                                                       : ConformanceOutcome::Failed;
    r.detail = e.what();
  } catch (const std::exception& e) {
    r.outcome = ConformanceOutcome::Failed;
    r.detail = e.what();
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

const char* outcome_name(ConformanceOutcome outcome) {
  switch (outcome) {
    case ConformanceOutcome::Rendered:
      return "rendered";
    case ConformanceOutcome::OutOfScope:
      return "out-of-scope";
    case ConformanceOutcome::Failed:
      return "FAILED";
  }
  return "?";
}

}  // namespace tr
