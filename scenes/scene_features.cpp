#include "scenes/scene_features.h"

#include <vector>

#include "core/bsdf/roughplastic.h"

namespace tr {

SceneFeatures scene_features(const SceneBuffers& scene) {
  SceneFeatures f;
  // Textures that are only tables read texel by texel, never evaluated as textures: a
  // roughplastic's precomputed terms (core/bsdf/roughplastic.h) and an envmap's texels
  // (core/emitters/envmap.h). The loader makes them for these alone (roughplastic materials
  // alike share theirs), so no other slot refers to them.
  std::vector<bool> table(scene.textures.size(), false);
  for (const Material& m : scene.materials) {
    f.bsdf_types |= 1u << m.type;
    f.material_flags |= m.flags;
    if (m.type == BSDF_BLEND) continue;  // its weight is looked up by the blend's own code
    const bool roughplastic = m.type == BSDF_ROUGHPLASTIC;
    if (roughplastic && m.param[ROUGHPLASTIC_TABLE].texture != NO_INDEX)
      table[m.param[ROUGHPLASTIC_TABLE].texture] = true;
    for (uint k = 0; k < MATERIAL_PARAM_COUNT; ++k)
      if (m.param[k].texture != NO_INDEX && !(roughplastic && k == ROUGHPLASTIC_TABLE))
        f.textured_slots |= 1u << k;
    if (m.opacity.texture != NO_INDEX) f.textured_slots |= 1u << MATERIAL_PARAM_COUNT;
  }
  for (const Emitter& e : scene.emitters) {
    f.emitter_types |= 1u << e.type;
    if (e.type == EMITTER_ENVMAP && e.texture != NO_INDEX) table[e.texture] = true;
  }
  for (const Shape& s : scene.shapes) f.shape_types |= 1u << s.type;
  for (size_t i = 0; i < scene.textures.size(); ++i)
    if (!table[i]) f.texture_types |= 1u << scene.textures[i].type;
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
