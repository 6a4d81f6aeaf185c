#include "materials.h"

#include <cmath>
#include <map>
#include <tuple>

#include "core/bsdf.h"
#include "core/material_slots.h"
#include "scene_access_local.h"

namespace tr::bsdf_suite {
namespace {

TexturedValue constant(vec3 v) {
  TexturedValue t;
  t.value = v;
  t.texture = NO_INDEX;
  return t;
}

Material blank(uint type) {
  Material m{};
  m.type = type;
  m.flags = 0u;
  m.eta = 1.0f;
  m.extra = 0.0f;
  m.opacity = constant(vec3(1.0f));
  for (uint i = 0; i < MATERIAL_PARAM_COUNT; ++i) m.param[i] = constant(vec3(0.0f));
  return m;
}

uint microfacet_flags(Distribution d, bool sample_visible) {
  return (d == Distribution::beckmann ? MATERIAL_BECKMANN : 0u) |
         (sample_visible ? MATERIAL_SAMPLE_VISIBLE : 0u);
}

const vec2 kUv(0.5f, 0.5f);

}  // namespace

Material diffuse(vec3 reflectance) {
  Material m = blank(BSDF_DIFFUSE);
  m.param[DIFFUSE_REFLECTANCE] = constant(reflectance);
  return m;
}

Material conductor(vec3 eta, vec3 k, vec3 specular_reflectance) {
  Material m = blank(BSDF_CONDUCTOR);
  m.param[CONDUCTOR_ETA] = constant(eta);
  m.param[CONDUCTOR_K] = constant(k);
  m.param[CONDUCTOR_SPECULAR_REFLECTANCE] = constant(specular_reflectance);
  return m;
}

Material roughconductor(Distribution d, float alpha_u, float alpha_v, bool sample_visible, vec3 eta,
                        vec3 k, vec3 specular_reflectance) {
  Material m = conductor(eta, k, specular_reflectance);
  m.type = BSDF_ROUGHCONDUCTOR;
  m.flags = microfacet_flags(d, sample_visible);
  m.param[CONDUCTOR_ALPHA_U] = constant(vec3(alpha_u));
  m.param[CONDUCTOR_ALPHA_V] = constant(vec3(alpha_v));
  return m;
}

Material dielectric(float eta, vec3 specular_reflectance, vec3 specular_transmittance) {
  Material m = blank(BSDF_DIELECTRIC);
  m.eta = eta;
  m.param[DIELECTRIC_SPECULAR_REFLECTANCE] = constant(specular_reflectance);
  m.param[DIELECTRIC_SPECULAR_TRANSMITTANCE] = constant(specular_transmittance);
  return m;
}

Material roughdielectric(Distribution d, float alpha_u, float alpha_v, bool sample_visible,
                         float eta, vec3 specular_reflectance, vec3 specular_transmittance) {
  Material m = dielectric(eta, specular_reflectance, specular_transmittance);
  m.type = BSDF_ROUGHDIELECTRIC;
  m.flags = microfacet_flags(d, sample_visible);
  m.param[DIELECTRIC_ALPHA_U] = constant(vec3(alpha_u));
  m.param[DIELECTRIC_ALPHA_V] = constant(vec3(alpha_v));
  return m;
}

Material thindielectric(float eta, vec3 specular_reflectance, vec3 specular_transmittance) {
  Material m = dielectric(eta, specular_reflectance, specular_transmittance);
  m.type = BSDF_THINDIELECTRIC;
  return m;
}

Material plastic(float eta, vec3 diffuse_reflectance, vec3 specular_reflectance, bool nonlinear) {
  Material m = blank(BSDF_PLASTIC);
  m.eta = eta;
  m.flags = nonlinear ? MATERIAL_NONLINEAR : 0u;
  m.param[PLASTIC_DIFFUSE_REFLECTANCE] = constant(diffuse_reflectance);
  m.param[PLASTIC_SPECULAR_REFLECTANCE] = constant(specular_reflectance);
  // Mitsuba's specular sampling weight s_mean / (d_mean + s_mean) over channel means, in
  // Material.extra (core/bsdf/plastic.h).
  float d_mean = (diffuse_reflectance.x + diffuse_reflectance.y + diffuse_reflectance.z) / 3.0f;
  float s_mean = (specular_reflectance.x + specular_reflectance.y + specular_reflectance.z) / 3.0f;
  m.extra = d_mean + s_mean > 0.0f ? s_mean / (d_mean + s_mean) : 0.5f;  // as the loader
  return m;
}

Material roughplastic(Distribution d, float alpha, bool sample_visible, float eta,
                      vec3 diffuse_reflectance, vec3 specular_reflectance, bool nonlinear) {
  Material m = plastic(eta, diffuse_reflectance, specular_reflectance, nonlinear);
  m.type = BSDF_ROUGHPLASTIC;
  m.flags |= microfacet_flags(d, sample_visible);
  m.param[PLASTIC_ALPHA] = constant(vec3(alpha));
  // The precomputed terms of core/bsdf/roughplastic.h, built with core/bsdf/roughplastic_table.h
  // as the loader does: T(mu_j) as a one-row texture, R_int in value.x. One per (distribution,
  // alpha, eta).
  static std::map<std::tuple<bool, float, float>, TexturedValue> tables;
  bool beckmann = d == Distribution::beckmann;
  auto key = std::make_tuple(beckmann, alpha, eta);
  auto it = tables.find(key);
  if (it == tables.end()) {
    Texture t{};
    t.type = TEXTURE_BITMAP;
    t.filter_mode = FILTER_BILINEAR;
    t.wrap_mode = WRAP_CLAMP;
    t.width = ROUGHPLASTIC_TABLE_RES;
    t.height = 1u;
    t.to_uv[0] = vec4(1.0f, 0.0f, 0.0f, 0.0f);
    t.to_uv[1] = vec4(0.0f, 1.0f, 0.0f, 0.0f);
    std::vector<vec4> texels;
    for (uint j = 0; j < ROUGHPLASTIC_TABLE_RES; ++j) {
      float T = roughplastic_external_transmittance(beckmann, alpha, eta, roughplastic_table_mu(j));
      texels.push_back(vec4(T, T, T, 1.0f));
    }
    TexturedValue v;
    v.value = vec3(roughplastic_internal_reflectance(beckmann, alpha, eta));
    v.texture = add_texture(t, texels);
    it = tables.emplace(key, v).first;
  }
  m.param[ROUGHPLASTIC_TABLE] = it->second;
  return m;
}

Material pplastic(Distribution d, float alpha_u, float alpha_v, bool sample_visible, float eta,
                  vec3 diffuse_reflectance, vec3 specular_reflectance) {
  Material m = plastic(eta, diffuse_reflectance, specular_reflectance, false);
  m.type = BSDF_PPLASTIC;
  m.flags = microfacet_flags(d, sample_visible);
  m.param[PPLASTIC_ALPHA_U] = constant(vec3(alpha_u));
  m.param[PPLASTIC_ALPHA_V] = constant(vec3(alpha_v));
  m.param[PPLASTIC_ETA] = constant(vec3(eta));
  return m;
}

Material principled(const PrincipledParameters& p) {
  Material m = blank(BSDF_PRINCIPLED);
  // The loader's eta <-> specular correspondence (Mitsuba principled.cpp):
  // eta = 2 / (1 - sqrt(0.08 specular)) - 1; with transmission, eta = 1 becomes 1.001 and
  // specular = 0 becomes 1e-3.
  float specular = p.specular;
  float eta = p.eta;
  if (eta > 0.0f) {
    if (p.spec_trans > 0.0f && eta == 1.0f) eta = 1.001f;
    specular = sqr((eta - 1.0f) / (eta + 1.0f)) / 0.08f;
  } else {
    if (p.spec_trans > 0.0f && specular == 0.0f) specular = 1e-3f;
    eta = 2.0f / (1.0f - std::sqrt(0.08f * specular)) - 1.0f;
  }
  m.eta = eta;
  m.param[PRINCIPLED_BASE_COLOR] = constant(p.base_color);
  m.param[PRINCIPLED_ROUGHNESS] = constant(vec3(p.roughness));
  m.param[PRINCIPLED_METALLIC] = constant(vec3(p.metallic));
  m.param[PRINCIPLED_FLATNESS] = constant(vec3(p.flatness));
  m.param[PRINCIPLED_SPEC_TINT] = constant(vec3(p.spec_tint));
  m.param[PRINCIPLED_ANISOTROPIC] = constant(vec3(p.anisotropic));
  m.param[PRINCIPLED_SHEEN] = constant(vec3(p.sheen));
  m.param[PRINCIPLED_SHEEN_TINT] = constant(vec3(p.sheen_tint));
  m.param[PRINCIPLED_CLEARCOAT] = constant(vec3(p.clearcoat));
  m.param[PRINCIPLED_CLEARCOAT_GLOSS] = constant(vec3(p.clearcoat_gloss));
  m.param[PRINCIPLED_SPEC_TRANS] = constant(vec3(p.spec_trans));
  m.param[PRINCIPLED_SAMPLING_RATES] = constant(p.sampling_rates);
  return m;
}

Material twosided(Material m) {
  m.flags |= MATERIAL_TWOSIDED;
  return m;
}

Material masked(Material m, float opacity) {
  m.flags |= MATERIAL_MASKED;
  m.opacity = constant(vec3(opacity));
  return m;
}

Material blend(const Material& bsdf_0, const Material& bsdf_1, float weight) {
  Material m = blank(BSDF_BLEND);
  m.param[BLEND_WEIGHT] = constant(vec3(weight));
  m.param[BLEND_BSDF_0] = constant(vec3(float(add_material(bsdf_0))));
  m.param[BLEND_BSDF_1] = constant(vec3(float(add_material(bsdf_1))));
  m.lobes = blend_lobes(bsdf_0, bsdf_1);
  return m;
}

Material normalmap(const Material& bsdf, vec3 normal, bool flip_invalid_normals,
                   bool use_shadowing_function) {
  Material m = blank(BSDF_NORMALMAP);
  m.param[NORMALMAP_NORMALMAP] = constant((normal + vec3(1.0f)) * 0.5f);
  m.param[NORMALMAP_BSDF] = constant(vec3(float(add_material(bsdf))));
  m.param[NORMALMAP_OPTIONS] = constant(
      vec3(flip_invalid_normals ? 1.0f : 0.0f, use_shadowing_function ? 1.0f : 0.0f, 0.0f));
  return m;
}

Material bumpmap(const Material& bsdf, vec2 slope, float scale, bool flip_invalid_normals,
                 bool use_shadowing_function) {
  Texture t{};
  t.type = TEXTURE_BITMAP;
  t.filter_mode = FILTER_BILINEAR;
  t.wrap_mode = WRAP_CLAMP;
  t.width = t.height = 2u;
  t.to_uv[0] = vec4(1.0f, 0.0f, 0.0f, 0.0f);
  t.to_uv[1] = vec4(0.0f, 1.0f, 0.0f, 0.0f);
  // Texel steps of slope / 2 over a texel of 1/2 in uv.
  vec2 step = 0.5f * slope;
  std::vector<vec4> texels = {vec4(0.0f), vec4(step.x), vec4(step.y), vec4(step.x + step.y)};
  Material m = blank(BSDF_BUMPMAP);
  m.param[BUMPMAP_HEIGHT].value = vec3(0.0f);
  m.param[BUMPMAP_HEIGHT].texture = add_texture(t, texels);
  m.param[BUMPMAP_BSDF] = constant(vec3(float(add_material(bsdf))));
  m.param[BUMPMAP_OPTIONS] = constant(
      vec3(flip_invalid_normals ? 1.0f : 0.0f, use_shadowing_function ? 1.0f : 0.0f, scale));
  return m;
}

bool bsdf_available(const Material& m) { return (bsdf_flags(m, kUv) & ~BSDF_NULL) != 0u; }

bool bsdf_type_available(uint type) {
  if (type == BSDF_BLEND)
    return bsdf_available(blend(diffuse(vec3(0.5f)), diffuse(vec3(0.5f)), 0.5f));
  return bsdf_available(blank(type));
}

namespace {

twinray::validation::BsdfSample validation_sample(const BsdfSample& s, float weight_scale) {
  twinray::validation::BsdfSample r;
  r.wo = s.wo;
  r.pdf = s.pdf;
  r.weight = s.weight * weight_scale;
  r.delta = (s.lobe & BSDF_DELTA) != 0u;
  r.lobe = s.lobe;
  return r;
}

}  // namespace

twinray::validation::BsdfUnderTest core_bsdf(const std::string& name, const Material& m,
                                             CoreCalls& calls) {
  twinray::validation::BsdfUnderTest b;
  b.name = name;
  b.sample = [m, &calls](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    return validation_sample(calls.bsdf_sample(m, kUv, wi, u1, u2), 1.0f);
  };
  b.pdf = [m, &calls](const glm::vec3& wi, const glm::vec3& wo) {
    return calls.bsdf_pdf(m, kUv, wi, wo);
  };
  b.eval = [m, &calls](const glm::vec3& wi, const glm::vec3& wo) {
    return calls.bsdf_eval(m, kUv, wi, wo);
  };
  b.eval_includes_cosine = true;
  return b;
}

twinray::validation::BsdfUnderTest energy_weights(const std::string& name, const Material& m,
                                                  CoreCalls& calls) {
  twinray::validation::BsdfUnderTest b = core_bsdf(name, m, calls);
  b.sample = [m, &calls](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    BsdfSample s = calls.bsdf_sample(m, kUv, wi, u1, u2);
    return validation_sample(s, s.eta * s.eta);
  };
  return b;
}

}  // namespace tr::bsdf_suite
