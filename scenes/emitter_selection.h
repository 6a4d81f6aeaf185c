// The opt-in emitter selections (core/scene_types.h, EMITTER_SELECTION_*), built over a loaded
// scene whose emitters are chosen as Mitsuba chooses them (by `sampling_weight`). Both keep
// sampling_weight as a factor: an emitter of weight 0 is never chosen, and the others' power
// is scaled by their weight.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace tr {

// "uniform" (Mitsuba's, the default), "power" or "bvh"; throws std::invalid_argument.
uint parse_emitter_selection(const std::string& name);
const char* emitter_selection_name(uint selection);

// Switches the buffers from the selection by sampling_weight to `selection`: POWER appends an
// alias table over estimated power times sampling_weight; BVH builds the light BVH
// (scenes/light_bvh_build.h) and the table of the infinite emitters.
void use_emitter_selection(SceneBuffers& b, uint selection);

}  // namespace tr
