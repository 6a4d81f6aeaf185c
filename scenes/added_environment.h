// `twinray render --envmap FILE [--envmap-scale S]` and `--constant RGB`: an environment emitter
// added to the parsed node tree of any scene format (XML, .scn, glTF), equal to editing the
// scene to declare
//   <emitter type="envmap"> <string name="filename" value="FILE"/> <float name="scale" value="S"/>
//   </emitter>                      or       <emitter type="constant"> <rgb name="radiance" .../>
// so that scenes that cannot state an environment (glTF) or have no emitter can be lit.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>

namespace tr {

struct Node;

struct AddedEnvironment {
  std::string envmap;  // an image Mitsuba's envmap reads (EXR, HDR, ...); "" for none
  double envmap_scale = 1.0;
  std::optional<glm::dvec3> constant;  // the radiance of a constant emitter
  bool any() const { return !envmap.empty() || constant.has_value(); }
};

// Parses "V" (grey) or "R,G,B": finite, non-negative numbers; std::invalid_argument otherwise.
glm::dvec3 parse_radiance(const std::string& text);

// Adds the environment to `root` (a parsed scene). Mitsuba holds one environment emitter a
// scene: a scene that declares a `constant` or `envmap` emitter is refused (SceneError at it).
void add_environment(Node& root, const AddedEnvironment& environment);

}  // namespace tr
