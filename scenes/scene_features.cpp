#include "scenes/scene_features.h"

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

bool features_cover(const SceneFeatures& outer, const SceneFeatures& inner) {
  auto covers = [](uint32_t o, uint32_t i) { return (i & ~o) == 0u; };
  return covers(outer.bsdf_types, inner.bsdf_types) &&
         covers(outer.emitter_types, inner.emitter_types) &&
         covers(outer.shape_types, inner.shape_types) &&
         covers(outer.texture_types, inner.texture_types) &&
         covers(outer.material_flags, inner.material_flags) &&
         covers(outer.integrator_types, inner.integrator_types) &&
         covers(outer.aov_types, inner.aov_types) &&
         covers(outer.sampler_types, inner.sampler_types) &&
         covers(outer.textured_slots, inner.textured_slots) &&
         covers(outer.emitter_selections, inner.emitter_selections);
}

}  // namespace tr
