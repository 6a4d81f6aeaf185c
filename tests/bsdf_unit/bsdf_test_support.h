// Scene data behind core/scene_access.h for the BSDF unit tests, and helpers to build
// materials and directions.
#pragma once

#include <vector>

#include "core/bsdf.h"
#include "core/scene_types.h"

namespace tr::test {

// Backing store of the scene_* accessors; tests fill what they use.
struct TestScene {
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<vec4> texels;
};
TestScene& test_scene();

TexturedValue constant(vec3 v);
TexturedValue constant(float v);
Material make_material(uint type);  // every parameter constant 0, eta 1

// Unit direction with cos(theta) = cos_theta at azimuth phi.
vec3 direction(float cos_theta, float phi);

// Mitsuba defaults of each plugin (parameters the plugin docs list, constant values).
Material diffuse(vec3 reflectance);
Material conductor(vec3 eta, vec3 k);
Material dielectric(float eta);
Material thin_dielectric(float eta);
// Microfacet models: `flags` takes MATERIAL_BECKMANN / MATERIAL_SAMPLE_VISIBLE.
Material rough_conductor(uint flags, float alpha_u, float alpha_v, vec3 eta, vec3 k);
Material rough_dielectric(uint flags, float alpha_u, float alpha_v, float eta);
// Plastics: Material.extra gets Mitsuba's specular sampling weight 1 / (mean(R_d) + 1).
Material plastic(vec3 diffuse_reflectance, float eta, bool nonlinear);
// principled with every parameter constant.
Material principled(const PrincipledParams& p);
// Builds the transmittance table as a texture of test_scene(), as the loader does.
Material rough_plastic(uint flags, float alpha, vec3 diffuse_reflectance, float eta,
                       bool nonlinear);

}  // namespace tr::test
