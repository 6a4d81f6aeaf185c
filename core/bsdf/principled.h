// Mitsuba 3 `principled` (src/bsdfs/principled.cpp, principledhelpers.h): the Disney BSDF of
// Burley, "Physically-Based Shading at Disney", SIGGRAPH 2012 course, with the specular
// transmission of Burley, "Extending the Disney BRDF to a BSDF with Integrated Subsurface
// Scattering", SIGGRAPH 2015 course, in Mitsuba's formulation:
//   diffuse    brdf base/pi |cos_o| lerp(f_d + f_retro, f_ss, flatness)        (2015 §3.1, 3.2)
//              with brdf = (1 - metallic)(1 - spec_trans); the sheen (2012 §5.3) rides on it
//   specular   GGX (anisotropic, alpha = roughness^2 stretched by sqrt(1 - 0.9 anisotropic)),
//              Fresnel blending the dielectric term, its tinted and metallic Schlick forms
//              F D G / (4 |cos_i|)                                             (2012 §5.4–5.6)
//   spec_trans rough-dielectric refraction (Walter et al. 2007, eq. 21) tinted sqrt(base),
//              weighted bsdf = (1 - metallic) spec_trans, radiance-scaled by 1/eta^2
//   clearcoat  GTR1 (2012 §B.2) with Schlick F0 = 0.04 and Smith-GGX G with alpha = 0.25,
//              clearcoat/4 Fcc Dcc Gcc |cos_o| (Mitsuba's normalisation)
// Lobes are sampled with Mitsuba's probabilities, scaled by the sampling rates in
// param[PRINCIPLED_SAMPLING_RATES]; sample() returns the mixture pdf and eval / pdf.
// Material.eta holds Mitsuba's m_eta: `eta`, or 2 / (1 - sqrt(0.08 specular)) - 1 from
// `specular` (specular = 0 raised to 1e-3, eta = 1 to 1.001 when spec_trans is given).
// Mitsuba's has_* switches only ever skip terms that vanish for a zero parameter, so each
// term is evaluated unconditionally here.
#ifndef TWINRAY_CORE_BSDF_PRINCIPLED_H
#define TWINRAY_CORE_BSDF_PRINCIPLED_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"
#include "core/microfacet.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

struct PrincipledParams {
  vec3 base_color;
  float roughness;
  float metallic;
  float spec_tint;
  float anisotropic;
  float sheen;
  float sheen_tint;
  float clearcoat;
  float clearcoat_gloss;
  float spec_trans;
  float flatness;
  float eta;
  float diffuse_rate;    // Mitsuba's diffuse_reflectance_sampling_rate
  float specular_rate;   // main_specular_sampling_rate
  float clearcoat_rate;  // clearcoat_sampling_rate
};

INLINE PrincipledParams principled_params(IN(Material) m, TexCoord uv) {
  PrincipledParams p;
  p.base_color = m.param[PRINCIPLED_BASE_COLOR].value;
  p.roughness = m.param[PRINCIPLED_ROUGHNESS].value.x;
  p.metallic = m.param[PRINCIPLED_METALLIC].value.x;
  p.spec_tint = m.param[PRINCIPLED_SPEC_TINT].value.x;
  p.anisotropic = m.param[PRINCIPLED_ANISOTROPIC].value.x;
  p.sheen = m.param[PRINCIPLED_SHEEN].value.x;
  p.sheen_tint = m.param[PRINCIPLED_SHEEN_TINT].value.x;
  p.clearcoat = m.param[PRINCIPLED_CLEARCOAT].value.x;
  p.clearcoat_gloss = m.param[PRINCIPLED_CLEARCOAT_GLOSS].value.x;
  p.spec_trans = m.param[PRINCIPLED_SPEC_TRANS].value.x;
  p.flatness = m.param[PRINCIPLED_FLATNESS].value.x;
  p.eta = m.eta;
  vec3 rates = m.param[PRINCIPLED_SAMPLING_RATES].value;
  p.diffuse_rate = rates.x;
  p.specular_rate = rates.y;
  p.clearcoat_rate = rates.z;
  return p;
}

INLINE uint principled_flags(IN(Material) m, TexCoord uv) {
  TexturedValue t = m.param[PRINCIPLED_SPEC_TRANS];
  bool transmits = t.texture != NO_INDEX || t.value.x > 0.0f;
  return BSDF_DIFFUSE_REFLECTION | BSDF_GLOSSY_REFLECTION |
         (transmits ? BSDF_GLOSSY_TRANSMISSION : 0u);
}

// Schlick's weight (1 - cos)^5 (Schlick 1994, eq. 15).
INLINE float principled_schlick_weight(float cos_theta) {
  float m = clamp(1.0f - cos_theta, 0.0f, 1.0f);
  return (m * m) * (m * m) * m;
}

// Schlick's approximation R0 + (1 - R0) w, with w taken on the denser side of the interface
// (the refracted cosine when arriving from the denser medium), Mitsuba's calc_schlick.
INLINE vec3 principled_schlick(vec3 r0, float cos_theta_i, float eta) {
  bool outside = cos_theta_i >= 0.0f;
  float eta_it = outside ? eta : 1.0f / eta;
  float eta_ti = outside ? 1.0f / eta : eta;
  float cos_theta_t = safe_sqrt(1.0f - (1.0f - cos_theta_i * cos_theta_i) * eta_ti * eta_ti);
  float w = eta_it > 1.0f ? principled_schlick_weight(abs(cos_theta_i))
                          : principled_schlick_weight(cos_theta_t);
  return w * (vec3(1.0f) - r0) + r0;
}

INLINE float principled_r0(float eta) { return sqr((eta - 1.0f) / (eta + 1.0f)); }

// Whether wi and wo lie on the sides of the microfacet m that reflection (or refraction)
// through it requires, with m turned toward wi's side of the macro surface.
INLINE bool principled_compatible(vec3 m, vec3 wi, vec3 wo, float cos_theta_i, bool reflection) {
  vec3 mi = mulsign(1.0f, cos_theta_i) * m;
  if (reflection) return dot(wi, mi) > 0.0f && dot(wo, mi) > 0.0f;
  return dot(wi, mi) > 0.0f && dot(wo, -mi) > 0.0f;
}

// The specular Fresnel term: on the front side a blend of the dielectric term, its
// spec_tint-ed Schlick form and the metallic Schlick form; behind, the dielectric term of
// the transmissive part only.
INLINE vec3 principled_fresnel(PrincipledParams p, float f_dielectric, float lum, float cos_theta_i,
                               bool front_side, float bsdf) {
  if (!front_side) return vec3(bsdf * f_dielectric);
  float eta_it = cos_theta_i >= 0.0f ? p.eta : 1.0f / p.eta;
  vec3 f_schlick = p.metallic * principled_schlick(p.base_color, cos_theta_i, p.eta);
  vec3 c_tint = lum > 0.0f ? p.base_color / lum : vec3(1.0f);
  f_schlick += (1.0f - p.metallic) * p.spec_tint *
               principled_schlick(c_tint * principled_r0(eta_it), cos_theta_i, p.eta);
  return vec3((1.0f - p.metallic) * (1.0f - p.spec_tint) * f_dielectric) + f_schlick;
}

// GGX parameters: alpha = roughness^2 stretched by aspect = sqrt(1 - 0.9 anisotropic)
// (Burley 2012, §B.2 "anisotropic"), at least 0.001.
INLINE Microfacet principled_specular_distribution(PrincipledParams p) {
  float r2 = p.roughness * p.roughness;
  float aspect = sqrt(1.0f - 0.9f * p.anisotropic);
  return microfacet_make(false, max(0.001f, r2 / aspect), max(0.001f, r2 * aspect), true);
}

// GTR1 (Burley 2012, §B.2 eq. 4): D = (a^2 - 1) / (pi log(a^2) (1 + (a^2 - 1) cos^2)),
// sampled by inverting its cos^2 CDF; a = lerp(0.1, 0.001, clearcoat_gloss).
INLINE float principled_gtr1_alpha(PrincipledParams p) {
  return 0.1f + (0.001f - 0.1f) * p.clearcoat_gloss;
}

INLINE float principled_gtr1_d(float alpha, vec3 m) {
  float a2 = alpha * alpha;
  float result = (a2 - 1.0f) / (PI * log(a2) * (1.0f + (a2 - 1.0f) * m.z * m.z));
  return result * m.z > 1e-20f ? result : 0.0f;
}

INLINE float principled_gtr1_pdf(float alpha, vec3 m) {
  return m.z < 0.0f ? 0.0f : m.z * principled_gtr1_d(alpha, m);
}

INLINE vec3 principled_gtr1_sample(float alpha, vec2 u) {
  float phi = 2.0f * PI * u.x;
  float a2 = alpha * alpha;
  float cos2 = (1.0f - pow(a2, 1.0f - u.y)) / (1.0f - a2);
  float sin_theta = sqrt(max(0.0f, 1.0f - cos2));
  float cos_theta = sqrt(max(0.0f, cos2));
  return vec3(cos(phi) * sin_theta, sin(phi) * sin_theta, cos_theta);
}

// Isotropic Smith G1 for GGX (Walter et al. 2007, eq. 34), the clearcoat's masking.
INLINE float principled_smith_ggx1(vec3 v, vec3 h, float alpha) {
  if (dot(v, h) * v.z <= 0.0f) return 0.0f;
  if (v.z == 1.0f) return 1.0f;
  float cos2 = v.z * v.z;
  float tan2 = (1.0f - cos2) / cos2;
  return 2.0f / (1.0f + sqrt(1.0f + alpha * alpha * tan2));
}

// Generalised half vector turned to the upper hemisphere; zero when undefined.
INLINE vec3 principled_half_vector(vec3 wi, vec3 wo, bool reflect, float eta_path) {
  vec3 h = reflect ? wi + wo : wi + wo * eta_path;
  float len2 = dot(h, h);
  if (!(len2 > 0.0f)) return vec3(0.0f);
  h = h / sqrt(len2);
  return h.z >= 0.0f ? h : -h;
}

// Unnormalised lobe selection weights (diffuse, clearcoat, spec_trans, spec_reflect) for the
// dielectric Fresnel term f at the specular microfacet.
INLINE vec4 principled_lobe_weights(PrincipledParams p, bool front_side, float f) {
  float bsdf = (1.0f - p.metallic) * p.spec_trans;
  float brdf = (1.0f - p.metallic) * (1.0f - p.spec_trans);
  if (!front_side) return vec4(0.0f, 0.0f, 1.0f - f, f);
  return vec4(brdf * p.diffuse_rate, 0.25f * p.clearcoat * p.clearcoat_rate,
              p.specular_rate * bsdf * (1.0f - f), p.specular_rate * (1.0f - bsdf * (1.0f - f)));
}

INLINE BsdfEvalPdf principled_eval_pdf_params(PrincipledParams p, vec3 wi, vec3 wo) {
  BsdfEvalPdf r = bsdf_eval_pdf_zero();
  float cos_i = wi.z;
  float cos_o = wo.z;
  if (cos_i == 0.0f) return r;
  float brdf = (1.0f - p.metallic) * (1.0f - p.spec_trans);
  float bsdf = (1.0f - p.metallic) * p.spec_trans;
  bool reflect = cos_i * cos_o > 0.0f;
  bool refract = cos_i * cos_o < 0.0f;
  bool front_side = cos_i > 0.0f;
  float eta_path = front_side ? p.eta : 1.0f / p.eta;
  float inv_eta_path = front_side ? 1.0f / p.eta : p.eta;
  vec3 h = principled_half_vector(wi, wo, reflect, eta_path);
  if (h.z == 0.0f) return r;
  Microfacet d = principled_specular_distribution(p);
  float wi_h = dot(wi, h);
  float wo_h = dot(wo, h);
  float f_dielectric = fresnel_dielectric_reflectance(wi_h, p.eta);
  bool reflection_ok = principled_compatible(h, wi, wo, cos_i, true);
  bool refraction_ok = principled_compatible(h, wi, wo, cos_i, false);

  // ---- The value.
  float D = microfacet_d(d, h);
  float G = microfacet_g(d, wi, wo, h);
  if (reflect && reflection_ok && f_dielectric > 0.0f) {
    float lum = luminance(p.base_color);
    vec3 F = principled_fresnel(p, f_dielectric, lum, wi_h, front_side, bsdf);
    r.f += F * (D * G / (4.0f * abs(cos_i)));
  }
  if (bsdf > 0.0f && refract && refraction_ok && f_dielectric < 1.0f) {
    float denom = wi_h + eta_path * wo_h;
    float t = abs(inv_eta_path * inv_eta_path * (1.0f - f_dielectric) * D * G * eta_path *
                  eta_path * wi_h * wo_h / (cos_i * denom * denom));
    r.f += sqrt(p.base_color) * (bsdf * t);
  }
  if (p.clearcoat > 0.0f && reflect && reflection_ok && front_side) {
    float f_cc = principled_schlick(vec3(0.04f), wi_h, p.eta).x;
    float d_cc = principled_gtr1_d(principled_gtr1_alpha(p), h);
    float g_cc = principled_smith_ggx1(wi, h, 0.25f) * principled_smith_ggx1(wo, h, 0.25f);
    r.f += vec3(p.clearcoat * 0.25f * f_cc * d_cc * g_cc * abs(cos_o));
  }
  if (brdf > 0.0f && reflect && front_side) {
    // Burley 2015 eq. 4 (retro-reflection) and §3.1 (Hanrahan-Krueger-like flattening).
    float fo = principled_schlick_weight(abs(cos_o));
    float fi = principled_schlick_weight(abs(cos_i));
    float f_diff = (1.0f - 0.5f * fi) * (1.0f - 0.5f * fo);
    float cos_theta_d = wo_h;
    float rr = 2.0f * p.roughness * cos_theta_d * cos_theta_d;
    float f_retro = rr * (fo + fi + fo * fi * (rr - 1.0f));
    float fss90 = rr / 2.0f;
    float fss = (1.0f + (fss90 - 1.0f) * fo) * (1.0f + (fss90 - 1.0f) * fi);
    float f_ss = 1.25f * (fss * (1.0f / (abs(cos_o) + abs(cos_i)) - 0.5f) + 0.5f);
    float lobe = (f_diff + f_retro) * (1.0f - p.flatness) + f_ss * p.flatness;
    r.f += p.base_color * (brdf * abs(cos_o) * INV_PI * lobe);
    if (p.sheen > 0.0f && 1.0f - p.metallic > 0.0f) {
      // Burley 2012 §5.3: Schlick-shaped sheen, tinted toward the base hue.
      float fd = principled_schlick_weight(abs(cos_theta_d));
      float lum = luminance(p.base_color);
      vec3 c_tint = lum > 0.0f ? p.base_color / lum : vec3(1.0f);
      vec3 c_sheen = vec3(1.0f) + (c_tint - vec3(1.0f)) * p.sheen_tint;
      r.f += c_sheen * (p.sheen * (1.0f - p.metallic) * fd * abs(cos_o));
    }
  }

  // ---- The density. Behind the surface only the transmissive part scatters (Mitsuba's
  // sample() refuses otherwise).
  if (!front_side && !(bsdf > 0.0f)) return r;
  vec4 w = principled_lobe_weights(p, front_side, f_dielectric);
  w /= w.x + w.y + w.z + w.w;
  float dh_dwo =
      reflect ? 1.0f / (4.0f * wo_h) : eta_path * eta_path * wo_h / sqr(wi_h + eta_path * wo_h);
  dh_dwo = abs(dh_dwo);
  float pdf = 0.0f;
  float spec = microfacet_pdf(d, front_side ? wi : -wi, h) * dh_dwo;
  if (reflect && reflection_ok)
    pdf += w.w * spec + w.y * principled_gtr1_pdf(principled_gtr1_alpha(p), h) * dh_dwo;
  if (reflect) pdf += w.x * square_to_cosine_hemisphere_pdf(wo);
  if (refract && refraction_ok) pdf += w.z * spec;
  r.pdf = pdf < FLOAT_MAX ? pdf : 0.0f;
  return r;
}

INLINE BsdfSample principled_sample_params(PrincipledParams p, vec3 wi, float u1, vec2 u2) {
  float cos_i = wi.z;
  if (cos_i == 0.0f) return bsdf_sample_failed();
  bool front_side = cos_i > 0.0f;
  float bsdf = (1.0f - p.metallic) * p.spec_trans;
  if (!front_side && !(bsdf > 0.0f)) return bsdf_sample_failed();
  vec3 h = microfacet_sample(principled_specular_distribution(p), front_side ? wi : -wi, u2);
  float cos_t;
  float eta_it;
  float eta_ti;
  float f = fresnel_dielectric(dot(wi, h), p.eta, cos_t, eta_it, eta_ti);
  vec4 w = principled_lobe_weights(p, front_side, f);
  w /= w.x + w.y + w.z + w.w;
  vec3 wo;
  uint lobe;
  float eta = 1.0f;
  if (u1 < w.x) {
    wo = square_to_cosine_hemisphere(u2);
    lobe = BSDF_DIFFUSE_REFLECTION;
    if (!(cos_i * wo.z > 0.0f)) return bsdf_sample_failed();
  } else if (u1 < w.x + w.y) {
    vec3 m = principled_gtr1_sample(principled_gtr1_alpha(p), u2);
    wo = reflect_about(wi, m);
    lobe = BSDF_GLOSSY_REFLECTION;
    if (!(principled_compatible(m, wi, wo, cos_i, true) && cos_i * wo.z > 0.0f))
      return bsdf_sample_failed();
  } else if (u1 < w.x + w.y + w.z) {
    wo = refract_about(wi, h, cos_t, eta_ti);
    lobe = BSDF_GLOSSY_TRANSMISSION;
    eta = eta_it;
    if (!(principled_compatible(h, wi, wo, cos_i, false) && cos_i * wo.z < 0.0f))
      return bsdf_sample_failed();
  } else {
    wo = reflect_about(wi, h);
    lobe = BSDF_GLOSSY_REFLECTION;
    if (!(principled_compatible(h, wi, wo, cos_i, true) && cos_i * wo.z > 0.0f))
      return bsdf_sample_failed();
  }
  return bsdf_sample_smooth(wo, principled_eval_pdf_params(p, wi, wo), eta, lobe);
}

INLINE BsdfEvalPdf principled_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  return principled_eval_pdf_params(principled_params(m, uv), wi, wo);
}

INLINE BsdfSample principled_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  return principled_sample_params(principled_params(m, uv), wi, u1, u2);
}

TR_NAMESPACE_END

#endif
