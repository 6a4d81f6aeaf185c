#include "gpu_backend/scene_features.h"

namespace tr {

SceneFeatures scene_features(const SceneBuffers& scene) {
  SceneFeatures f;
  for (const Material& m : scene.materials) {
    f.bsdf_types |= 1u << m.type;
    f.material_flags |= m.flags;
    if (m.type == BSDF_BLEND) continue;  // its weight is looked up by the blend's own code
    for (uint k = 0; k < MATERIAL_PARAM_COUNT; ++k)
      if (m.param[k].texture != NO_INDEX) f.textured_slots |= 1u << k;
    if (m.opacity.texture != NO_INDEX) f.textured_slots |= 1u << MATERIAL_PARAM_COUNT;
  }
  for (const Emitter& e : scene.emitters) f.emitter_types |= 1u << e.type;
  for (const Shape& s : scene.shapes) f.shape_types |= 1u << s.type;
  for (const Texture& t : scene.textures) f.texture_types |= 1u << t.type;
  f.integrator_types = 1u << scene.globals.integrator.type;
  const Integrator& it = scene.globals.integrator;
  for (uint i = 0; i < it.aov_count; ++i) f.aov_types |= 1u << it.aov_types[i / 4][i % 4];
  f.sampler_types = 1u << scene.globals.sampler_params.type;
  f.emitter_selections = 1u << scene.globals.emitter_selection;
  return f;
}

SceneFeatures all_features() {
  return SceneFeatures{~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u};
}

}  // namespace tr
