#include "gpu_backend/scene_features.h"

namespace tr {

SceneFeatures scene_features(const SceneBuffers& scene) {
  SceneFeatures f;
  for (const Material& m : scene.materials) {
    f.bsdf_types |= 1u << m.type;
    f.material_flags |= m.flags;
  }
  for (const Emitter& e : scene.emitters) f.emitter_types |= 1u << e.type;
  for (const Shape& s : scene.shapes) f.shape_types |= 1u << s.type;
  for (const Texture& t : scene.textures) f.texture_types |= 1u << t.type;
  f.integrator_types = 1u << scene.globals.integrator.type;
  const Integrator& it = scene.globals.integrator;
  for (uint i = 0; i < it.aov_count; ++i) f.aov_types |= 1u << it.aov_types[i / 4][i % 4];
  f.sampler_types = 1u << scene.globals.sampler_params.type;
  return f;
}

SceneFeatures all_features() { return SceneFeatures{~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u}; }

}  // namespace tr
