// core/scene_access.h for the BSDF validation suite: materials, textures and texels come from
// small local vectors (constant parameters everywhere; textures only for roughplastic's
// precomputed table; materials for the children of blends); everything else is out of scope
// here and throws.
#include "scene_access_local.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene_access.h"

namespace tr {
namespace {

std::vector<Material> materials;
std::vector<Texture> textures;
std::vector<vec4> texels;

[[noreturn]] void out_of_scope(const char* what) {
  throw std::logic_error(std::string(what) + " is not available in tests/bsdf");
}

}  // namespace

namespace bsdf_suite {

uint add_texture(Texture t, const std::vector<vec4>& new_texels) {
  t.texel_offset = uint(texels.size());
  texels.insert(texels.end(), new_texels.begin(), new_texels.end());
  textures.push_back(t);
  return uint(textures.size() - 1);
}

uint add_material(const Material& m) {
  materials.push_back(m);
  return uint(materials.size() - 1);
}

const std::vector<Material>& local_materials() { return materials; }
const std::vector<Texture>& local_textures() { return textures; }
const std::vector<vec4>& local_texels() { return texels; }

}  // namespace bsdf_suite

const SceneGlobals& scene_globals() { out_of_scope("scene_globals"); }
const Material& scene_material(uint index) { return materials.at(index); }
const Texture& scene_texture(uint index) { return textures.at(index); }
vec4 scene_texel(uint index) { return texels.at(index); }
const Emitter& scene_emitter(uint) { out_of_scope("scene_emitter"); }
AliasEntry scene_alias(uint) { out_of_scope("scene_alias"); }
const LightNode& scene_light_node(uint) { out_of_scope("scene_light_node"); }
const Shape& scene_shape(uint) { out_of_scope("scene_shape"); }
const Instance& scene_instance(uint) { out_of_scope("scene_instance"); }
vec3 scene_position(uint) { out_of_scope("scene_position"); }
vec3 scene_normal(uint) { out_of_scope("scene_normal"); }
vec2 scene_uv(uint) { out_of_scope("scene_uv"); }
uint scene_index(uint) { out_of_scope("scene_index"); }
uint scene_attribute(uint) { out_of_scope("scene_attribute"); }

}  // namespace tr
