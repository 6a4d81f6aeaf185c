// Mitsuba 3 `roughplastic` (src/bsdfs/roughplastic.cpp): a diffuse base under a rough
// dielectric coating (Weidlich & Wilkie, "Arbitrarily Layered Micro-Facet Surfaces",
// GRAPHITE 2007, in Mitsuba's form), lit from the front side:
//   f cos_o = F(wi.h) D(h) G(wi, wo, h) / (4 cos_i)                       (Walter et al. 2007)
//           + R_d / (1 - R_int R') T(cos_i) T(cos_o) cos_o / (pi eta^2)
// T the external transmittance of the rough interface and R_int its internal reflectance
// (core/bsdf/roughplastic_table.h), R' = R_d when `nonlinear`, 1 else. Sampling chooses the
// microfacet lobe with probability (1 - T_i) w / ((1 - T_i) w + T_i (1 - w)), w = Material.extra
// the specular sampling weight (as for plastic), else the cosine-weighted base; pdf and weight
// are those of the whole mixture, as in Mitsuba.
//
// Storage: alpha is a constant (Mitsuba takes no texture; the tables depend on it) and
// param[ROUGHPLASTIC_TABLE] holds value.x = R_int and, as its texture, a one-row texture of
// ROUGHPLASTIC_TABLE_RES texels whose x channel is T(mu_j), mu_j = roughplastic_table_mu(j),
// both computed by the loader with the functions of roughplastic_table.h.
#ifndef TWINRAY_CORE_BSDF_ROUGHPLASTIC_H
#define TWINRAY_CORE_BSDF_ROUGHPLASTIC_H

#include "core/bsdf/common.h"
#include "core/bsdf/plastic.h"
#include "core/bsdf/roughplastic_table.h"
#include "core/fresnel.h"
#include "core/material_slots.h"
#include "core/microfacet.h"
#include "core/scene_access.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

const uint ROUGHPLASTIC_TABLE = 3u;  // Material.param slot of the precomputed terms

INLINE uint roughplastic_flags(IN(Material) m, TexCoord uv) {
  return BSDF_GLOSSY_REFLECTION | BSDF_DIFFUSE_REFLECTION;
}

INLINE Microfacet roughplastic_distribution(IN(Material) m) {
  float alpha = m.param[PLASTIC_ALPHA].value.x;
  return microfacet_make((m.flags & MATERIAL_BECKMANN) != 0u, alpha, alpha,
                         (m.flags & MATERIAL_SAMPLE_VISIBLE) != 0u);
}

// T(cos_theta) by linear interpolation between the table entries (Mitsuba's lerp_gather).
INLINE float roughplastic_transmittance(IN(Material) m, float cos_theta) {
  REF(Texture) table = scene_texture(m.param[ROUGHPLASTIC_TABLE].texture);
  float x = cos_theta * float(ROUGHPLASTIC_TABLE_RES - 1u);
  uint index = min(uint(x), ROUGHPLASTIC_TABLE_RES - 2u);
  float v0 = scene_texel(table.texel_offset + index).x;
  float v1 = scene_texel(table.texel_offset + index + 1u).x;
  return mix(v0, v1, x - float(index));
}

INLINE BsdfEvalPdf roughplastic_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  if (wi.z <= 0.0f || wo.z <= 0.0f) return bsdf_eval_pdf_zero();
  Microfacet d = roughplastic_distribution(m);
  vec3 h = normalize(wo + wi);
  float F = fresnel_dielectric_reflectance(dot(wi, h), m.eta);
  vec3 value = m.param[PLASTIC_SPECULAR_REFLECTANCE].value *
               (F * microfacet_d(d, h) * microfacet_g(d, wi, wo, h) / (4.0f * wi.z));
  float t_i = roughplastic_transmittance(m, wi.z);
  float t_o = roughplastic_transmittance(m, wo.z);
  vec3 diff = plastic_diffuse_albedo(m, uv, m.param[ROUGHPLASTIC_TABLE].value.x);
  float p_specular = plastic_specular_probability(1.0f - t_i, m.extra);
  // Half-vector density times dh/dwo = 1 / (4 wo.h), as for roughconductor.
  float specular = microfacet_pdf(d, wi, h) / (4.0f * dot(wo, h));
  return bsdf_eval_pdf_make(
      value + diff * (INV_PI * wo.z * t_i * t_o / (m.eta * m.eta)),
      p_specular * specular + (1.0f - p_specular) * square_to_cosine_hemisphere_pdf(wo));
}

INLINE BsdfSample roughplastic_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  if (wi.z <= 0.0f) return bsdf_sample_failed();
  float t_i = roughplastic_transmittance(m, wi.z);
  float p_specular = plastic_specular_probability(1.0f - t_i, m.extra);
  bool specular = u1 < p_specular;
  vec3 wo = specular ? reflect_about(wi, microfacet_sample(roughplastic_distribution(m), wi, u2))
                     : square_to_cosine_hemisphere(u2);
  if (!(wo.z > 0.0f)) return bsdf_sample_failed();
  return bsdf_sample_smooth(wo, roughplastic_eval_pdf(m, uv, wi, wo), 1.0f,
                            specular ? BSDF_GLOSSY_REFLECTION : BSDF_DIFFUSE_REFLECTION);
}

TR_NAMESPACE_END

#endif
