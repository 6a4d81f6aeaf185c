// Scene loading: the public entry point.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "scenes/added_environment.h"
#include "scenes/guide_aovs.h"
#include "scenes/scene.h"

namespace tr {

struct LoadOptions {
  std::map<std::string, std::string> defines;  // -D name=value, override <default> values
  std::vector<std::string> search_paths;       // -a PATH, searched for files the scene names
  // A define that no $name uses is an error unless this is set (a tool that passes the same
  // defines to many scenes, as Mitsuba's documentation script passes spp).
  bool unused_defines_allowed = false;
  // --aov: when not empty, the scene's integrator is wrapped in an `aov` integrator with these
  // output variables (scenes/guide_aovs.h), whatever the scene's format.
  std::vector<GuideAov> guide_aovs;
  // --emitter-selection: EMITTER_SELECTION_* (scenes/emitter_selection.h); Mitsuba's by default.
  uint emitter_selection = EMITTER_SELECTION_UNIFORM;
  // --envmap / --constant: an environment added to the scene (scenes/added_environment.h).
  AddedEnvironment environment;
  // --camera, glTF scenes only: "" the file's first camera node (framing the scene when it has
  // none), "auto" framing the scene's bounds, or N the file's cameras[N] (scenes/gltf/).
  std::string camera;
  // --strict-gltf: a glTF field that does not map exactly is an error instead of a warning.
  bool strict_gltf = false;
};

// Parses and builds the scene: a Mitsuba 3 XML file or, by the extension, a `.scn` JSON scene
// (scenes/scn/) or a glTF 2.0 scene (`.gltf`, `.glb`: scenes/gltf/), whose mapping warnings it
// prints on stderr once the scene is built; throws SceneError("file:line: what and why") on bad
// input.
Scene load_scene(const std::string& path, const LoadOptions& options);

}  // namespace tr
