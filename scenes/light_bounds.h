// What the opt-in emitter selections (core/scene_types.h, EMITTER_SELECTION_*) know of each
// emitter: an estimate of its power and, for emitters with a position, the bounds of where and
// towards which directions it emits (pbrt-v4 §12.6.1, LightBounds). The bounds must hold
// everything the emitter can send, or the light BVH would never choose an emitter that lights a
// point; the power only shapes the variance.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "scenes/scene.h"

namespace tr {

// A cone of directions: those within acos(cos_theta) of the unit vector w (pbrt-v4 §3.9.4).
struct DirectionCone {
  glm::dvec3 w{0.0, 0.0, 1.0};
  double cos_theta = 1.0;
  bool empty = true;

  static DirectionCone entire_sphere() { return {glm::dvec3(0.0, 0.0, 1.0), -1.0, false}; }
  static DirectionCone around(const glm::dvec3& w) { return {w, 1.0, false}; }
};

// The smallest cone holding both (pbrt-v4 §3.9.4, Union).
DirectionCone cone_union(const DirectionCone& a, const DirectionCone& b);

struct LightBounds {
  bool infinite = false;  // constant, envmap, directional: no position, chosen apart
  double phi = 0.0;       // estimated power, W (infinite emitters: through the scene's disk)
  glm::dvec3 lo{0.0}, hi{0.0};
  DirectionCone normals;     // surface normals or emission axes
  double cos_theta_e = 0.0;  // emission reaches acos(cos_theta_e) beyond `normals`
};

// One entry per emitter of the buffers, in their order.
std::vector<LightBounds> emitter_light_bounds(const SceneBuffers& b);

}  // namespace tr
