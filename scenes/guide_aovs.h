// `twinray render --aov LIST`: denoiser guide buffers (albedo, normals, depth, ...) written
// with the colour. The scene's integrator is wrapped in Mitsuba 3's `aov` integrator
// (scenes/build_sensor.cpp, core/integrators/aov.h) on the parsed node tree, so it applies to
// every scene format alike and equals editing the scene to
//   <integrator type="aov"> <string name="aovs" value="NAME:TYPE,..."/> <the scene's own>
//   </integrator>
// (the scene's integrator, or Mitsuba's default `path` where it declares none).
#pragma once

#include <string>
#include <vector>

namespace tr {

struct Node;

struct GuideAov {
  std::string name;  // the channels are NAME.<suffix>, e.g. albedo.R, sh_normal.X, depth.T
  std::string type;  // a type of Mitsuba's aov integrator: albedo, depth, sh_normal, ...
};

// The AOV types twinray's aov integrator implements, in Mitsuba's order, comma-separated.
const char* guide_aov_types();

// Parses LIST: comma-separated entries TYPE or NAME:TYPE, spaces around them ignored (NAME: a
// letter, then letters, digits or '_'; TYPE alone names its channels after itself). Throws
// std::invalid_argument with a one-line message on an empty entry, an unknown type (the message
// lists the valid ones), a bad or repeated name, or more entries than the aov integrator holds.
std::vector<GuideAov> parse_guide_aovs(const std::string& list);

// Wraps the top-level integrator of `root` (a parsed scene) in an `aov` integrator with
// `aovs`, which must be valid for parse_guide_aovs (std::invalid_argument otherwise). A scene
// whose integrator is already `aov` is refused (SceneError at that integrator: its AOVs and
// --aov's would have to be merged, and twinray nests no aov in aov), as is a `moment` one
// (twinray nests no moment in aov); one without an integrator gets Mitsuba's default `path`.
void wrap_in_guide_aovs(Node& root, const std::vector<GuideAov>& aovs);

}  // namespace tr
