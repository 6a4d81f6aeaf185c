// Mitsuba 3 `roughdielectric` (src/bsdfs/roughdielectric.cpp): microfacet reflection and
// refraction at a rough interface lit from both sides (Walter et al. 2007):
//   reflection    f cos_o = F D G / (4 |cos_i|)                                     (eq. 20)
//   transmission  f cos_o = |(1 - F) D G eta^2 (wi.h)(wo.h) / (cos_i (wi.h + eta wo.h)^2)|
//                           / eta^2                                                 (eq. 21)
// with h the generalised half vector (eq. 16), eta = n_t / n_i for wi's side, and the final
// 1 / eta^2 the radiance scaling of refraction that Mitsuba adds for radiance transport.
// Sampling draws a normal (visible normals, or D cos with Walter's roughness widening
// 1.2 - 0.2 sqrt|cos_i| of §5.3), then reflects with probability F(wi.h), else refracts; the
// density carries the half-vector Jacobians (eqs. 14 and 17).
#ifndef TWINRAY_CORE_BSDF_ROUGHDIELECTRIC_H
#define TWINRAY_CORE_BSDF_ROUGHDIELECTRIC_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"
#include "core/microfacet.h"

TR_NAMESPACE_BEGIN

INLINE uint roughdielectric_flags(IN(Material) m, TexCoord uv) {
  return BSDF_GLOSSY_REFLECTION | BSDF_GLOSSY_TRANSMISSION;
}

INLINE Microfacet roughdielectric_distribution(IN(Material) m, TexCoord uv) {
  return microfacet_make((m.flags & MATERIAL_BECKMANN) != 0u, m.param[DIELECTRIC_ALPHA_U].value.x,
                         m.param[DIELECTRIC_ALPHA_V].value.x,
                         (m.flags & MATERIAL_SAMPLE_VISIBLE) != 0u);
}

// The distribution normals are drawn from: Walter et al.'s widened roughness without
// visible-normal sampling.
INLINE Microfacet roughdielectric_sampling_distribution(Microfacet d, float cos_theta_i) {
  if (!d.sample_visible) {
    float scale = 1.2f - 0.2f * sqrt(abs(cos_theta_i));
    d.alpha_u *= scale;
    d.alpha_v *= scale;
  }
  return d;
}

// Generalised half vector (Walter et al. eq. 16) in the upper hemisphere; zero when wi and
// wo leave it undefined.
INLINE vec3 roughdielectric_half_vector(vec3 wi, vec3 wo, float eta) {
  vec3 h = wi.z * wo.z > 0.0f ? wi + wo : wi + wo * eta;
  float len2 = dot(h, h);
  if (!(len2 > 0.0f)) return vec3(0.0f);
  h = h / sqrt(len2);
  return h.z >= 0.0f ? h : -h;
}

// f cos_o at wo through its half vector h (eqs. 20 and 21).
INLINE vec3 roughdielectric_eval_half(IN(Material) m, Microfacet d, vec3 wi, vec3 wo, vec3 h,
                                      float eta, bool reflect) {
  float cos_i = wi.z;
  float D = microfacet_d(d, h);
  float G = microfacet_g(d, wi, wo, h);
  if (D == 0.0f || G == 0.0f) return vec3(0.0f);
  float F = fresnel_dielectric_reflectance(dot(wi, h), m.eta);
  if (reflect) {
    return m.param[DIELECTRIC_SPECULAR_REFLECTANCE].value * (F * D * G / (4.0f * abs(cos_i)));
  }
  float wi_h = dot(wi, h);
  float wo_h = dot(wo, h);
  float denom = wi_h + eta * wo_h;
  float value = abs((1.0f - F) * D * G * wi_h * wo_h / (cos_i * denom * denom));
  return m.param[DIELECTRIC_SPECULAR_TRANSMITTANCE].value * value;
}

// Density of h for wi, times the probability of the chosen lobe and the Jacobian dh/dwo.
INLINE float roughdielectric_pdf_half(Microfacet d, vec3 wi, vec3 wo, vec3 h, float eta,
                                      float m_eta, bool reflect) {
  float wi_h = dot(wi, h);
  float wo_h = dot(wo, h);
  float dh_dwo;
  if (reflect) {
    dh_dwo = 1.0f / (4.0f * wo_h);
  } else {
    float denom = wi_h + eta * wo_h;
    dh_dwo = eta * eta * wo_h / (denom * denom);
  }
  Microfacet ds = roughdielectric_sampling_distribution(d, wi.z);
  float prob = microfacet_pdf(ds, wi.z >= 0.0f ? wi : -wi, h);
  float F = fresnel_dielectric_reflectance(wi_h, m_eta);
  prob *= reflect ? F : 1.0f - F;
  return prob * abs(dh_dwo);
}

INLINE BsdfEvalPdf roughdielectric_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  BsdfEvalPdf r = bsdf_eval_pdf_zero();
  float cos_i = wi.z;
  if (cos_i == 0.0f) return r;
  bool reflect = cos_i * wo.z > 0.0f;
  float eta = cos_i > 0.0f ? m.eta : 1.0f / m.eta;
  vec3 h = roughdielectric_half_vector(wi, wo, eta);
  if (h.z == 0.0f) return r;
  Microfacet d = roughdielectric_distribution(m, uv);
  r.f = roughdielectric_eval_half(m, d, wi, wo, h, eta, reflect);
  // The sides must agree between micro- and macro-surface (the chi+ terms of G).
  if (!(dot(wi, h) * wi.z <= 0.0f || dot(wo, h) * wo.z <= 0.0f)) {
    float pdf = roughdielectric_pdf_half(d, wi, wo, h, eta, m.eta, reflect);
    r.pdf = pdf < FLOAT_MAX ? pdf : 0.0f;
  }
  return r;
}

INLINE BsdfSample roughdielectric_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  float cos_i = wi.z;
  if (cos_i == 0.0f) return bsdf_sample_failed();
  Microfacet d = roughdielectric_distribution(m, uv);
  Microfacet ds = roughdielectric_sampling_distribution(d, cos_i);
  vec3 h = microfacet_sample(ds, cos_i >= 0.0f ? wi : -wi, u2);
  float wi_h = dot(wi, h);
  if (!(wi_h * cos_i > 0.0f)) return bsdf_sample_failed();
  float cos_t;
  float eta_it;
  float eta_ti;
  float F = fresnel_dielectric(wi_h, m.eta, cos_t, eta_it, eta_ti);
  bool reflect = u1 <= F;
  vec3 wo = reflect ? reflect_about(wi, h) : refract_about(wi, h, cos_t, eta_ti);
  // A direction on the wrong side for its lobe is masked (G1(wo, h) = 0).
  if (reflect ? !(wo.z * cos_i > 0.0f) : !(wo.z * cos_i < 0.0f)) return bsdf_sample_failed();
  // Density and value at wo as eval_pdf() sees it, so that both agree exactly with the
  // sample (Mitsuba writes the weight in closed form — G1(wo, h) for visible normals — which
  // is the same up to rounding, and up to D / D' of the widened sampling distribution that
  // it leaves out).
  return bsdf_sample_smooth(wo, roughdielectric_eval_pdf(m, uv, wi, wo), reflect ? 1.0f : eta_it,
                            reflect ? BSDF_GLOSSY_REFLECTION : BSDF_GLOSSY_TRANSMISSION);
}

TR_NAMESPACE_END

#endif
