// The scene of one pass of a Mitsuba 3 reference (see make_reference): a copy of a Mitsuba
// 3 XML scene, self-contained so that it can live in another folder, in which
//   - every <include> is replaced by the children of the included file's <scene> (searched,
//     like Mitsuba 3.8.0 src/core/parser.cpp does, beside the including file and then in the
//     scene's folder), and each relative <path> that exists beside its file is made absolute;
//   - the top-level integrator is wrapped in Mitsuba's `moment` integrator unless it is one
//     (a scene without an integrator gets moment(path), Mitsuba's default integrator);
//   - the film (hdrfilm, OpenEXR output) stores float32 components;
//   - the sampler has the pass's `seed` and `sample_count`.
// Mitsuba must still be run with `-a <scene folder>` so that the relative file names of
// meshes and textures resolve as they did for the original scene.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

namespace tr {

// A scene this tool cannot derive a pass from; what() is "file[:line]: what and why".
struct PassSceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PassSettings {
  std::uint32_t seed = 0;
  std::uint32_t spp = 0;
  // -D values given to Mitsuba; only read to resolve a `$name` integrator type.
  std::map<std::string, std::string> defines;
};

// The XML text of the pass scene of `scene_path`.
std::string pass_scene_xml(const std::string& scene_path, const PassSettings& settings);

}  // namespace tr
