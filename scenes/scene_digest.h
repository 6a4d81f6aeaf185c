#pragma once

#include <string>

#include "scenes/scene.h"

namespace tr {

// A fingerprint of everything both backends read of a loaded scene (every record of its
// SceneBuffers, and the CPU's traversal mode): equal for the same scene file, defines and
// referenced files. 16 hex digits.
std::string scene_digest(const Scene& scene);

}  // namespace tr
