// Mitsuba 3 `roughconductor` (src/bsdfs/roughconductor.cpp): Cook-Torrance microfacet
// reflection lit from the front side,
//   f(wi, wo) = F(wi.h) D(h) G1(wi, h) G1(wo, h) / (4 cos_i cos_o),   h = (wi + wo) / |wi + wo|
// (Walter et al. 2007, eq. 20), F the exact conductor Fresnel term, sampled through the
// microfacet normal with the reflection Jacobian dh/dwo = 1 / (4 |wo.h|) (Walter et al. eq. 14).
#ifndef TWINRAY_CORE_BSDF_ROUGHCONDUCTOR_H
#define TWINRAY_CORE_BSDF_ROUGHCONDUCTOR_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"
#include "core/microfacet.h"

TR_NAMESPACE_BEGIN

INLINE uint roughconductor_flags(IN(Material) m, TexCoord uv) { return BSDF_GLOSSY_REFLECTION; }

INLINE Microfacet roughconductor_distribution(IN(Material) m, TexCoord uv) {
  return microfacet_make((m.flags & MATERIAL_BECKMANN) != 0u, m.param[CONDUCTOR_ALPHA_U].value.x,
                         m.param[CONDUCTOR_ALPHA_V].value.x,
                         (m.flags & MATERIAL_SAMPLE_VISIBLE) != 0u);
}

INLINE BsdfEvalPdf roughconductor_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  BsdfEvalPdf r = bsdf_eval_pdf_zero();
  if (wi.z <= 0.0f || wo.z <= 0.0f) return r;
  Microfacet d = roughconductor_distribution(m, uv);
  vec3 h = normalize(wi + wo);
  float D = microfacet_d(d, h);
  if (D != 0.0f) {
    float G = microfacet_g(d, wi, wo, h);
    vec3 F =
        fresnel_conductor(dot(wi, h), m.param[CONDUCTOR_ETA].value, m.param[CONDUCTOR_K].value);
    // f cos_o = F D G / (4 cos_i).
    r.f = F * m.param[CONDUCTOR_SPECULAR_REFLECTANCE].value * (D * G / (4.0f * wi.z));
  }
  // Density of h times dh/dwo = 1 / (4 wo.h) (Walter et al. 2007, eq. 14).
  if (!(dot(wi, h) <= 0.0f || dot(wo, h) <= 0.0f))
    r.pdf = microfacet_pdf(d, wi, h) / (4.0f * dot(wo, h));
  return r;
}

INLINE BsdfSample roughconductor_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  if (wi.z <= 0.0f) return bsdf_sample_failed();
  vec3 h = microfacet_sample(roughconductor_distribution(m, uv), wi, u2);
  vec3 wo = reflect_about(wi, h);
  if (!(wo.z > 0.0f)) return bsdf_sample_failed();
  return bsdf_sample_smooth(wo, roughconductor_eval_pdf(m, uv, wi, wo), 1.0f,
                            BSDF_GLOSSY_REFLECTION);
}

TR_NAMESPACE_END

#endif
