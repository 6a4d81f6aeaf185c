// The local scene store behind core/scene_access.h in tests/bsdf: textures the suite's
// materials need (roughplastic's precomputed transmittance table) and the children of blends
// are registered here.
#ifndef TWINRAY_TESTS_BSDF_SCENE_ACCESS_LOCAL_H
#define TWINRAY_TESTS_BSDF_SCENE_ACCESS_LOCAL_H

#include <vector>

#include "core/scene_types.h"

namespace tr::bsdf_suite {

// Appends the texels, points t.texel_offset at them and returns the new texture's index.
uint add_texture(Texture t, const std::vector<vec4>& texels);

// Appends a material (a blend's child, or a GPU query's material) and returns its index.
uint add_material(const Material& m);

// Everything registered so far (a GPU copy of the store uploads these).
const std::vector<Material>& local_materials();
const std::vector<Texture>& local_textures();
const std::vector<vec4>& local_texels();

}  // namespace tr::bsdf_suite

#endif
