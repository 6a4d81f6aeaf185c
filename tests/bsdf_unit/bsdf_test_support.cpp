#include "bsdf_test_support.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "core/scene_access.h"

namespace tr {

namespace test {

TestScene& test_scene() {
  static TestScene scene;
  return scene;
}

TexturedValue constant(vec3 v) {
  TexturedValue t;
  t.value = v;
  t.texture = NO_INDEX;
  return t;
}

TexturedValue constant(float v) { return constant(vec3(v)); }

Material make_material(uint type) {
  Material m{};
  m.type = type;
  m.flags = 0u;
  m.eta = 1.0f;
  m.extra = 0.0f;
  m.opacity = constant(1.0f);
  for (uint i = 0; i < MATERIAL_PARAM_COUNT; ++i) m.param[i] = constant(0.0f);
  return m;
}

vec3 direction(float cos_theta, float phi) {
  float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  return vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

Material diffuse(vec3 reflectance) {
  Material m = make_material(BSDF_DIFFUSE);
  m.param[DIFFUSE_REFLECTANCE] = constant(reflectance);
  return m;
}

Material conductor(vec3 eta, vec3 k) {
  Material m = make_material(BSDF_CONDUCTOR);
  m.param[CONDUCTOR_ETA] = constant(eta);
  m.param[CONDUCTOR_K] = constant(k);
  m.param[CONDUCTOR_SPECULAR_REFLECTANCE] = constant(1.0f);
  return m;
}

Material dielectric(float eta) {
  Material m = make_material(BSDF_DIELECTRIC);
  m.eta = eta;
  m.param[DIELECTRIC_SPECULAR_REFLECTANCE] = constant(1.0f);
  m.param[DIELECTRIC_SPECULAR_TRANSMITTANCE] = constant(1.0f);
  return m;
}

Material thin_dielectric(float eta) {
  Material m = dielectric(eta);
  m.type = BSDF_THINDIELECTRIC;
  return m;
}

Material principled(const PrincipledParams& p) {
  Material m = make_material(BSDF_PRINCIPLED);
  m.eta = p.eta;
  m.param[PRINCIPLED_BASE_COLOR] = constant(p.base_color);
  m.param[PRINCIPLED_ROUGHNESS] = constant(p.roughness);
  m.param[PRINCIPLED_METALLIC] = constant(p.metallic);
  m.param[PRINCIPLED_SPEC_TINT] = constant(p.spec_tint);
  m.param[PRINCIPLED_ANISOTROPIC] = constant(p.anisotropic);
  m.param[PRINCIPLED_SHEEN] = constant(p.sheen);
  m.param[PRINCIPLED_SHEEN_TINT] = constant(p.sheen_tint);
  m.param[PRINCIPLED_CLEARCOAT] = constant(p.clearcoat);
  m.param[PRINCIPLED_CLEARCOAT_GLOSS] = constant(p.clearcoat_gloss);
  m.param[PRINCIPLED_SPEC_TRANS] = constant(p.spec_trans);
  m.param[PRINCIPLED_FLATNESS] = constant(p.flatness);
  m.param[PRINCIPLED_SAMPLING_RATES] =
      constant(vec3(p.diffuse_rate, p.specular_rate, p.clearcoat_rate));
  return m;
}

Material rough_conductor(uint flags, float alpha_u, float alpha_v, vec3 eta, vec3 k) {
  Material m = conductor(eta, k);
  m.type = BSDF_ROUGHCONDUCTOR;
  m.flags = flags;
  m.param[CONDUCTOR_ALPHA_U] = constant(alpha_u);
  m.param[CONDUCTOR_ALPHA_V] = constant(alpha_v);
  return m;
}

Material rough_dielectric(uint flags, float alpha_u, float alpha_v, float eta) {
  Material m = dielectric(eta);
  m.type = BSDF_ROUGHDIELECTRIC;
  m.flags = flags;
  m.param[DIELECTRIC_ALPHA_U] = constant(alpha_u);
  m.param[DIELECTRIC_ALPHA_V] = constant(alpha_v);
  return m;
}

Material plastic(vec3 diffuse_reflectance, float eta, bool nonlinear) {
  Material m = make_material(BSDF_PLASTIC);
  m.eta = eta;
  m.flags = nonlinear ? MATERIAL_NONLINEAR : 0u;
  m.param[PLASTIC_DIFFUSE_REFLECTANCE] = constant(diffuse_reflectance);
  m.param[PLASTIC_SPECULAR_REFLECTANCE] = constant(1.0f);
  float d_mean = (diffuse_reflectance.x + diffuse_reflectance.y + diffuse_reflectance.z) / 3.0f;
  m.extra = 1.0f / (d_mean + 1.0f);
  return m;
}

Material rough_plastic(uint flags, float alpha, vec3 diffuse_reflectance, float eta,
                       bool nonlinear) {
  Material m = plastic(diffuse_reflectance, eta, nonlinear);
  m.type = BSDF_ROUGHPLASTIC;
  m.flags |= flags;
  m.param[PLASTIC_ALPHA] = constant(alpha);
  // One table per (distribution, alpha, eta), as the loader would share them.
  static std::map<std::tuple<bool, float, float>, std::pair<uint, float>> tables;
  bool beckmann = (flags & MATERIAL_BECKMANN) != 0u;
  auto key = std::make_tuple(beckmann, alpha, eta);
  auto it = tables.find(key);
  if (it == tables.end()) {
    TestScene& scene = test_scene();
    Texture table{};
    table.type = TEXTURE_BITMAP;
    table.texel_offset = uint(scene.texels.size());
    table.width = ROUGHPLASTIC_TABLE_RES;
    table.height = 1u;
    for (uint j = 0; j < ROUGHPLASTIC_TABLE_RES; ++j) {
      float t = roughplastic_external_transmittance(beckmann, alpha, eta, roughplastic_table_mu(j));
      scene.texels.push_back(vec4(t, 0.0f, 0.0f, 0.0f));
    }
    scene.textures.push_back(table);
    float r_int = roughplastic_internal_reflectance(beckmann, alpha, eta);
    it = tables.emplace(key, std::make_pair(uint(scene.textures.size() - 1), r_int)).first;
  }
  m.param[ROUGHPLASTIC_TABLE].texture = it->second.first;
  m.param[ROUGHPLASTIC_TABLE].value = vec3(it->second.second);
  return m;
}

}  // namespace test

// The BSDFs read materials and textures only; any other access is a test bug.
[[noreturn]] static void not_in_bsdf_tests(const char* what) {
  throw std::logic_error(std::string(what) + " is not available in the BSDF unit tests");
}

const SceneGlobals& scene_globals() { not_in_bsdf_tests("scene_globals"); }
const Material& scene_material(uint index) { return test::test_scene().materials.at(index); }
const Texture& scene_texture(uint index) { return test::test_scene().textures.at(index); }
vec4 scene_texel(uint index) { return test::test_scene().texels.at(index); }
const Emitter& scene_emitter(uint) { not_in_bsdf_tests("scene_emitter"); }
AliasEntry scene_alias(uint) { not_in_bsdf_tests("scene_alias"); }
const LightNode& scene_light_node(uint) { not_in_bsdf_tests("scene_light_node"); }
const Shape& scene_shape(uint) { not_in_bsdf_tests("scene_shape"); }
const Instance& scene_instance(uint) { not_in_bsdf_tests("scene_instance"); }
vec3 scene_position(uint) { not_in_bsdf_tests("scene_position"); }
vec3 scene_normal(uint) { not_in_bsdf_tests("scene_normal"); }
vec2 scene_uv(uint) { not_in_bsdf_tests("scene_uv"); }
uint scene_index(uint) { not_in_bsdf_tests("scene_index"); }
uint scene_attribute(uint) { not_in_bsdf_tests("scene_attribute"); }

}  // namespace tr
