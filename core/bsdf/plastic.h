// Mitsuba 3 `plastic` (src/bsdfs/plastic.cpp): a diffuse base under a smooth dielectric
// coating, lit from the front side. A delta specular reflection weighted by the Fresnel
// reflectance F_i, plus the base seen through the interface (Weidlich & Wilkie, "Arbitrarily
// Layered Micro-Facet Surfaces", GRAPHITE 2007, with the internal-scattering series summed
// as in Mitsuba):
//   f cos_o = R_d / (1 - F_dr_int R') (1 - F_i)(1 - F_o) cos_o / (pi eta^2)
// with F_dr_int = fresnel_diffuse_reflectance(1 / eta) and R' = R_d when `nonlinear`, 1 else.
// The specular lobe is sampled with probability F_i w / (F_i w + (1 - F_i)(1 - w)), w the
// specular sampling weight s_mean / (d_mean + s_mean) of Mitsuba, over texture means; the
// loader stores w in Material.extra.
#ifndef TWINRAY_CORE_BSDF_PLASTIC_H
#define TWINRAY_CORE_BSDF_PLASTIC_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

INLINE uint plastic_flags(IN(Material) m, TexCoord uv) {
  return BSDF_DELTA_REFLECTION | BSDF_DIFFUSE_REFLECTION;
}

// Probability of choosing the specular lobe given the external reflectance (F_i for plastic,
// 1 - T_i for roughplastic) and the specular sampling weight. When both lobe terms vanish
// the weight alone decides.
INLINE float plastic_specular_probability(float reflectance, float specular_weight) {
  // Quadrature can put roughplastic's T a few ulps above 1.
  reflectance = clamp(reflectance, 0.0f, 1.0f);
  float p_specular = reflectance * specular_weight;
  float p_diffuse = (1.0f - reflectance) * (1.0f - specular_weight);
  float total = p_specular + p_diffuse;
  return total > 0.0f ? p_specular / total : specular_weight;
}

// The diffuse base after internal reflections: R_d / (1 - F_dr R'), R' = R_d if nonlinear.
INLINE vec3 plastic_diffuse_albedo(IN(Material) m, TexCoord uv, float internal_reflectance) {
  vec3 diff = m.param[PLASTIC_DIFFUSE_REFLECTANCE].value;
  vec3 denom = (m.flags & MATERIAL_NONLINEAR) != 0u ? vec3(1.0f) - diff * internal_reflectance
                                                    : vec3(1.0f - internal_reflectance);
  return diff / denom;
}

INLINE BsdfEvalPdf plastic_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  if (wi.z <= 0.0f || wo.z <= 0.0f) return bsdf_eval_pdf_zero();
  float f_i = fresnel_dielectric_reflectance(wi.z, m.eta);
  float f_o = fresnel_dielectric_reflectance(wo.z, m.eta);
  vec3 diff = plastic_diffuse_albedo(m, uv, fresnel_diffuse_reflectance(1.0f / m.eta));
  float p_diffuse = 1.0f - plastic_specular_probability(f_i, m.extra);
  float cosine_pdf = square_to_cosine_hemisphere_pdf(wo);
  return bsdf_eval_pdf_make(diff * (cosine_pdf * (1.0f - f_i) * (1.0f - f_o) / (m.eta * m.eta)),
                            cosine_pdf * p_diffuse);
}

INLINE BsdfSample plastic_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  if (wi.z <= 0.0f) return bsdf_sample_failed();
  float f_i = fresnel_dielectric_reflectance(wi.z, m.eta);
  float p_specular = plastic_specular_probability(f_i, m.extra);
  if (u1 < p_specular) {
    vec3 weight = m.param[PLASTIC_SPECULAR_REFLECTANCE].value * (f_i / p_specular);
    return bsdf_sample_make(reflect_local(wi), p_specular, weight, 1.0f, BSDF_DELTA_REFLECTION);
  }
  vec3 wo = square_to_cosine_hemisphere(u2);
  return bsdf_sample_smooth(wo, plastic_eval_pdf(m, uv, wi, wo), 1.0f, BSDF_DIFFUSE_REFLECTION);
}

TR_NAMESPACE_END

#endif
