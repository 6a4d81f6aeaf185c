#include "materials.h"

#include "core/bsdf.h"
#include "core/material_slots.h"

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
  return m;
}

Material roughplastic(Distribution d, float alpha, bool sample_visible, float eta,
                      vec3 diffuse_reflectance, vec3 specular_reflectance, bool nonlinear) {
  Material m = plastic(eta, diffuse_reflectance, specular_reflectance, nonlinear);
  m.type = BSDF_ROUGHPLASTIC;
  m.flags |= microfacet_flags(d, sample_visible);
  m.param[PLASTIC_ALPHA] = constant(vec3(alpha));
  return m;
}

Material principled(const PrincipledParameters& p) {
  Material m = blank(BSDF_PRINCIPLED);
  m.eta = p.eta;
  m.param[PRINCIPLED_BASE_COLOR] = constant(p.base_color);
  m.param[PRINCIPLED_ROUGHNESS] = constant(vec3(p.roughness));
  m.param[PRINCIPLED_METALLIC] = constant(vec3(p.metallic));
  m.param[PRINCIPLED_SPECULAR] = constant(vec3(p.specular));
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

bool bsdf_available(const Material& m) { return (bsdf_flags(m, kUv) & ~BSDF_NULL) != 0u; }

twinray::validation::BsdfUnderTest core_bsdf(const std::string& name, const Material& m) {
  twinray::validation::BsdfUnderTest b;
  b.name = name;
  b.sample = [m](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    BsdfSample s = bsdf_sample(m, kUv, wi, u1, u2);
    twinray::validation::BsdfSample r;
    r.wo = s.wo;
    r.pdf = s.pdf;
    r.weight = s.weight;
    r.delta = (s.lobe & BSDF_DELTA) != 0u;
    r.lobe = s.lobe;
    return r;
  };
  b.pdf = [m](const glm::vec3& wi, const glm::vec3& wo) { return bsdf_pdf(m, kUv, wi, wo); };
  b.eval = [m](const glm::vec3& wi, const glm::vec3& wo) { return bsdf_eval(m, kUv, wi, wo); };
  b.eval_includes_cosine = true;
  return b;
}

twinray::validation::BsdfUnderTest energy_weights(const std::string& name, const Material& m) {
  twinray::validation::BsdfUnderTest b = core_bsdf(name, m);
  b.sample = [m](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    BsdfSample s = bsdf_sample(m, kUv, wi, u1, u2);
    twinray::validation::BsdfSample r;
    r.wo = s.wo;
    r.pdf = s.pdf;
    r.weight = s.weight * (s.eta * s.eta);
    r.delta = (s.lobe & BSDF_DELTA) != 0u;
    r.lobe = s.lobe;
    return r;
  };
  return b;
}

}  // namespace tr::bsdf_suite
