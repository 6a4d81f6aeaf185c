// Scene-folder conformance: load every Mitsuba scene of a folder and render it at a few samples
// per pixel, sorting each into rendered, refused by design (a plugin out of twinray's scope,
// named) or failed (the message). The `twinray conformance` verb.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "validation/harness/scene_render.h"

namespace tr {

enum class ConformanceOutcome { Rendered, OutOfScope, Failed };

struct ConformanceOptions {
  std::uint32_t spp = 1;                  // also given as -D spp=... where the scene asks for $spp
  std::vector<std::string> search_paths;  // -a
  BackendRenderer render;                 // required
  std::string backend = "cpu";
  std::uint32_t threads = 0;  // 0: all cores
  std::string preview_dir;    // where to write <scene>.png previews; empty: none
};

struct ConformanceResult {
  std::string scene;  // path of the XML file
  ConformanceOutcome outcome = ConformanceOutcome::Failed;
  std::string detail;  // the plugin (refused) or the one-line message (failed)
  double seconds = 0.0;
};

// The *.xml files directly inside `folder`, sorted by name.
std::vector<std::string> conformance_scenes(const std::string& folder);

// Loads and renders one scene; never throws for a bad scene (that is an outcome).
ConformanceResult check_conformance(const std::string& scene, const ConformanceOptions& options);

const char* outcome_name(ConformanceOutcome outcome);

}  // namespace tr
