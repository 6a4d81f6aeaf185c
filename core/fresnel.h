// Fresnel reflectance of smooth interfaces and the mirror/refraction directions, in the local
// shading frame (+z = normal), with Mitsuba 3's conventions (include/mitsuba/render/fresnel.h):
// `eta` is the relative IOR int/ext and a negative cos_theta_i means arrival from inside.
#ifndef TWINRAY_CORE_FRESNEL_H
#define TWINRAY_CORE_FRESNEL_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// Unpolarised reflectance of a dielectric interface: the average of the squared s and p
// amplitude ratios (Born & Wolf, Principles of Optics, §1.5.2; pbrt-v4 eq. 9.5). Also returns
// the signed cosine of the refracted direction (0 under total internal reflection) and the
// relative IORs eta_it = n_t/n_i and eta_ti = n_i/n_t for the side wi lies on. Index-matched
// interfaces reflect nothing; grazing incidence reflects everything.
INLINE float fresnel_dielectric(float cos_theta_i, float eta, OUT(float) cos_theta_t,
                                OUT(float) eta_it, OUT(float) eta_ti) {
  bool outside = cos_theta_i >= 0.0f;
  eta_it = outside ? eta : 1.0f / eta;
  eta_ti = outside ? 1.0f / eta : eta;
  // Snell's law: cos^2 theta_t = 1 - eta_ti^2 sin^2 theta_i.
  float cos_theta_t_sqr = 1.0f - eta_ti * eta_ti * (1.0f - cos_theta_i * cos_theta_i);
  float cos_i = abs(cos_theta_i);
  float cos_t = safe_sqrt(cos_theta_t_sqr);
  float a_s = (cos_i - eta_it * cos_t) / (cos_i + eta_it * cos_t);
  float a_p = (cos_t - eta_it * cos_i) / (cos_t + eta_it * cos_i);
  float r = 0.5f * (a_s * a_s + a_p * a_p);
  if (eta == 1.0f)
    r = 0.0f;
  else if (cos_i == 0.0f)
    r = 1.0f;
  cos_theta_t = cos_theta_i >= 0.0f ? -cos_t : cos_t;
  return r;
}

INLINE float fresnel_dielectric_reflectance(float cos_theta_i, float eta) {
  float cos_theta_t;
  float eta_it;
  float eta_ti;
  return fresnel_dielectric(cos_theta_i, eta, cos_theta_t, eta_it, eta_ti);
}

// Unpolarised reflectance of a conductor with complex IOR eta + i k, per channel, for
// cos_theta_i >= 0. Exact Fresnel equations for an absorbing medium in the closed form of
// pbrt-v3 §8.2.1 (FrConductor), as Mitsuba's fresnel_conductor evaluates them:
//   a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2)^2 + 4 eta^2 k^2),  a = sqrt((a^2+b^2 + t1) / 2)
//   R_s = (a^2+b^2 + cos^2 - 2 a cos) / (a^2+b^2 + cos^2 + 2 a cos)
//   R_p = R_s (cos^2 (a^2+b^2) + sin^4 - 2 a cos sin^2) / (cos^2 (a^2+b^2) + sin^4 + 2 a cos sin^2)
INLINE vec3 fresnel_conductor(float cos_theta_i, vec3 eta, vec3 k) {
  float cos2 = cos_theta_i * cos_theta_i;
  float sin2 = 1.0f - cos2;
  float sin4 = sin2 * sin2;
  vec3 t1 = eta * eta - k * k - vec3(sin2);
  vec3 a2_plus_b2 = sqrt(max(t1 * t1 + 4.0f * eta * eta * k * k, vec3(0.0f)));
  vec3 a = sqrt(max(0.5f * (a2_plus_b2 + t1), vec3(0.0f)));
  vec3 term1 = a2_plus_b2 + vec3(cos2);
  vec3 term2 = 2.0f * cos_theta_i * a;
  // Near index matching (eta -> 1, k -> 0) term1 and term2 cancel; rounding must not make
  // the reflectance negative; both vanish together only at grazing incidence on an
  // index-matched surface, where the limit of any mismatch is total reflection.
  vec3 r_s = max((term1 - term2) / max(term1 + term2, vec3(1e-30f)), vec3(0.0f));
  r_s = mix(r_s, vec3(1.0f), lessThanEqual(term1 + term2, vec3(0.0f)));
  vec3 term3 = a2_plus_b2 * cos2 + vec3(sin4);
  vec3 term4 = term2 * sin2;
  // eta = k = 0 at normal incidence makes the ratio 0/0; its limit is 1.
  vec3 ratio = (term3 - term4) / max(term3 + term4, vec3(1e-30f));
  vec3 r_p = r_s * mix(ratio, vec3(1.0f), lessThanEqual(term3 + term4, vec3(0.0f)));
  return 0.5f * (r_s + r_p);
}

// Hemispherically averaged (diffuse) Fresnel reflectance F_dr(eta) = 2 \int F(mu, eta) mu dmu
// by the fits Mitsuba uses (fresnel_diffuse_reflectance): d'Eon & Irving, "A Quantized-
// Diffusion Model for Rendering Translucent Materials", SIGGRAPH 2011 (a quintic in 1/eta,
// rel. error < 0.3% up to eta = 10) for eta >= 1, and Egan & Hilgeman 1973 for
// 0.5 <= eta < 1. Below 0.5 Egan & Hilgeman's fit leaves its range (it exceeds 1 near
// eta = 0.27), so there F_dr follows from the reciprocity of the interface's transmittance
// (T(mu_i) from either side, weighted by the radiance scaling eta^2, agrees), which gives
// 1 - F_dr(eta) = eta^2 (1 - F_dr(1 / eta)).
INLINE float fresnel_diffuse_reflectance_external(float eta) {
  float inv_eta = 1.0f / eta;
  return 0.919317f +
         inv_eta * (-3.4793f +
                    inv_eta * (6.75335f +
                               inv_eta * (-7.80989f + inv_eta * (4.98554f + inv_eta * -1.36881f))));
}

INLINE float fresnel_diffuse_reflectance(float eta) {
  if (eta >= 1.0f) return fresnel_diffuse_reflectance_external(eta);
  if (eta < 0.5f)
    return 1.0f - eta * eta * (1.0f - fresnel_diffuse_reflectance_external(1.0f / eta));
  return 0.0636f / eta + eta * (eta * -1.4399f + 0.7099f) + 0.6681f;
}

// Mirror direction about the normal (+z) and about a microfacet normal m. The sampled direction
// is PRECISE (core/prelude.h): pdf() and eval() of it must see the rounded direction returned,
// not a half vector the shader compiler recovered algebraically from wi + wo.
INLINE vec3 reflect_local(vec3 wi) { return vec3(-wi.x, -wi.y, wi.z); }
INLINE vec3 reflect_about(vec3 wi, vec3 m) {
  PRECISE vec3 wo = 2.0f * dot(wi, m) * m - wi;
  return wo;
}

// Refraction about +z / about m, given cos_theta_t and eta_ti from fresnel_dielectric
// (Walter et al. 2007, eq. 40).
INLINE vec3 refract_local(vec3 wi, float cos_theta_t, float eta_ti) {
  return vec3(-eta_ti * wi.x, -eta_ti * wi.y, cos_theta_t);
}
INLINE vec3 refract_about(vec3 wi, vec3 m, float cos_theta_t, float eta_ti) {
  PRECISE vec3 wo = m * (dot(wi, m) * eta_ti + cos_theta_t) - wi * eta_ti;
  return wo;
}

TR_NAMESPACE_END

#endif
