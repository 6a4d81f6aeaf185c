// The scene's feature masks: which BSDFs, emitters, shapes, ... its records use. Both backends
// compile the core for the features a scene has (core/prelude.h's TR_HAS_* guards): the GPU
// passes them to every shader stage as the specialization constants of shaders/features.glsl
// (constant_id 0..9, in this struct's order), the CPU picks the smallest of its precompiled
// kernels that covers them (cpu_backend/cpu_kernels.h).
#pragma once

#include <cstdint>

#include "scenes/scene.h"

namespace tr {

struct SceneFeatures {
  uint32_t bsdf_types = 0;        // bit BSDF_*
  uint32_t emitter_types = 0;     // bit EMITTER_*
  uint32_t shape_types = 0;       // bit SHAPE_*
  uint32_t texture_types = 0;     // bit TEXTURE_*
  uint32_t material_flags = 0;    // union of Material.flags
  uint32_t integrator_types = 0;  // bit INTEGRATOR_*
  uint32_t aov_types = 0;         // bit AOV_* (0: the scene writes no AOVs)
  uint32_t sampler_types = 0;     // bit SAMPLER_*
  // Bit k: a leaf (non-blend) material textures parameter slot k; bit MATERIAL_PARAM_COUNT:
  // its mask opacity (core/bsdf.h, material_at).
  uint32_t textured_slots = 0;
  uint32_t emitter_selections = 0;  // bit EMITTER_SELECTION_*
};

SceneFeatures scene_features(const SceneBuffers& scene);

// Every bit set: the all-features pipeline (kernel).
SceneFeatures all_features();

// Whether every feature of `inner` is one of `outer`'s.
bool features_cover(const SceneFeatures& outer, const SceneFeatures& inner);

}  // namespace tr
