// tr::Material records with constant parameters (Mitsuba 3 parameter meanings, slots of
// core/material_slots.h), and the adapter that exposes core/bsdf.h to twinray::validation.
#ifndef TWINRAY_TESTS_BSDF_MATERIALS_H
#define TWINRAY_TESTS_BSDF_MATERIALS_H

#include <string>

#include "core/scene_types.h"
#include "core_calls.h"
#include "twinray_validation.h"

namespace tr::bsdf_suite {

enum class Distribution { ggx, beckmann };

Material diffuse(vec3 reflectance);
Material conductor(vec3 eta, vec3 k, vec3 specular_reflectance);
Material roughconductor(Distribution d, float alpha_u, float alpha_v, bool sample_visible, vec3 eta,
                        vec3 k, vec3 specular_reflectance);
Material dielectric(float eta, vec3 specular_reflectance, vec3 specular_transmittance);
Material roughdielectric(Distribution d, float alpha_u, float alpha_v, bool sample_visible,
                         float eta, vec3 specular_reflectance, vec3 specular_transmittance);
Material thindielectric(float eta, vec3 specular_reflectance, vec3 specular_transmittance);
Material plastic(float eta, vec3 diffuse_reflectance, vec3 specular_reflectance, bool nonlinear);
Material roughplastic(Distribution d, float alpha, bool sample_visible, float eta,
                      vec3 diffuse_reflectance, vec3 specular_reflectance, bool nonlinear);
Material pplastic(Distribution d, float alpha_u, float alpha_v, bool sample_visible, float eta,
                  vec3 diffuse_reflectance, vec3 specular_reflectance);

// Every `principled` parameter (Mitsuba names); the sampling rates are Mitsuba's defaults
// unless set. `eta` and `specular` are tied as the loader ties them.
struct PrincipledParameters {
  vec3 base_color = vec3(0.5f);
  float roughness = 0.5f;
  float metallic = 0.0f;
  float specular = 0.5f;
  float spec_tint = 0.0f;
  float anisotropic = 0.0f;
  float sheen = 0.0f;
  float sheen_tint = 0.0f;
  float clearcoat = 0.0f;
  float clearcoat_gloss = 0.0f;
  float spec_trans = 0.0f;
  float flatness = 0.0f;
  float eta = 0.0f;  // > 0: sets `eta` (and specular from it); 0: eta from `specular`
  vec3 sampling_rates = vec3(1.0f);  // diffuse, main specular, clearcoat
};
Material principled(const PrincipledParameters& p);

Material twosided(Material m);
Material masked(Material m, float opacity);
// blendbsdf (1 - weight) bsdf_0 + weight bsdf_1; the children go to the local material store.
Material blend(const Material& bsdf_0, const Material& bsdf_1, float weight);
// normalmap around bsdf with a constant normal (stored as Mitsuba's texture value (n + 1) / 2).
Material normalmap(const Material& bsdf, vec3 normal, bool flip_invalid_normals,
                   bool use_shadowing_function);
// bumpmap around bsdf with a planar height h = slope . (u, v) (a 2x2 bilinear bitmap, clamped),
// so that at uv = (0.5, 0.5) the height gradient is scale * slope; on bsdf_surface_flat() the
// perturbed normal is normalize(-scale slope.x, -scale slope.y, 1).
Material bumpmap(const Material& bsdf, vec2 slope, float scale, bool flip_invalid_normals,
                 bool use_shadowing_function);

// Whether core/bsdf.h dispatches this material's type (its flags are non-zero).
bool bsdf_available(const Material& m);
bool bsdf_type_available(uint type);

// sample/pdf/eval of bsdf_sample/bsdf_pdf/bsdf_eval at uv = (0.5, 0.5), through `calls`; delta
// = a BSDF_DELTA lobe (delta reflection/transmission or the mask's null lobe).
twinray::validation::BsdfUnderTest core_bsdf(const std::string& name, const Material& m,
                                             CoreCalls& calls);

// The same sampler with energy (importance) weights: transmitted radiance weights carry
// (eta_i / eta_t)^2 = 1 / eta^2 (Veach 1997, §5.2), which the albedo bound must not count.
twinray::validation::BsdfUnderTest energy_weights(const std::string& name, const Material& m,
                                                  CoreCalls& calls);

}  // namespace tr::bsdf_suite

#endif
