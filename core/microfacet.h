// Anisotropic GGX and Beckmann microfacet distributions with Smith masking and (visible)
// normal sampling, with the conventions of Mitsuba 3's MicrofacetDistribution
// (include/mitsuba/render/microfacet.h): alphas are clamped to 1e-4, the sampled density is
// D(m) cos(theta_m) or, with visible-normal sampling, the distribution of visible normals.
//   D, G1, normal sampling: Walter et al., "Microfacet Models for Refraction through Rough
//     Surfaces", EGSR 2007, eqs. 25-28 (Beckmann), 33-35 (GGX), anisotropic forms after
//     Heitz, "Understanding the Masking-Shadowing Function", JCGT 3(2) 2014, eqs. 71-72, 86.
//   Visible normals: Heitz & d'Eon, "Importance Sampling Microfacet-Based BSDFs using the
//     Distribution of Visible Normals", EGSR 2014 (stretch, sample the slope for alpha = 1,
//     rotate, unstretch; Beckmann slope by inverting eq. 14 numerically) and Heitz, "Sampling
//     the GGX Distribution of Visible Normals", JCGT 7(4) 2018 (GGX, in the concentric-disk
//     form Mitsuba uses).
#ifndef TWINRAY_CORE_MICROFACET_H
#define TWINRAY_CORE_MICROFACET_H

#include "core/prelude.h"
#include "core/special_functions.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

const float MICROFACET_MIN_ALPHA = 1e-4f;
const float INV_SQRT_PI = 0.56418958354775628695f;

struct Microfacet {
  bool beckmann;        // GGX otherwise
  bool sample_visible;  // sample the distribution of visible normals
  float alpha_u;
  float alpha_v;
};

INLINE Microfacet microfacet_make(bool beckmann, float alpha_u, float alpha_v,
                                  bool sample_visible) {
  Microfacet d;
  d.beckmann = beckmann;
  d.sample_visible = sample_visible;
  d.alpha_u = max(alpha_u, MICROFACET_MIN_ALPHA);
  d.alpha_v = max(alpha_v, MICROFACET_MIN_ALPHA);
  return d;
}

// Normal distribution D(m) (Walter et al. eqs. 25 and 33, anisotropic: Heitz 2014 eqs. 71, 86).
INLINE float microfacet_d(Microfacet d, vec3 m) {
  float cos_theta = m.z;
  if (cos_theta <= 0.0f) return 0.0f;
  float cos_theta_2 = cos_theta * cos_theta;
  float xu = m.x / d.alpha_u;
  float yv = m.y / d.alpha_v;
  float result;
  if (d.beckmann) {
    result = exp(-(xu * xu + yv * yv) / cos_theta_2) /
             (PI * d.alpha_u * d.alpha_v * cos_theta_2 * cos_theta_2);
  } else {
    float s = xu * xu + yv * yv + cos_theta_2;
    result = 1.0f / (PI * d.alpha_u * d.alpha_v * s * s);
  }
  return result * cos_theta > 1e-20f ? result : 0.0f;
}

// Smith's masking term G1(v, m) for the uncorrelated-height model (Walter et al. eqs. 27, 34);
// Beckmann through Walter et al.'s rational approximation (eq. 27, < 0.35% error). Zero where
// v would see the back of the microfacet (Walter et al. eq. 7, the chi+ factor).
INLINE float microfacet_smith_g1(Microfacet d, vec3 v, vec3 m) {
  float xy_alpha_2 = sqr(d.alpha_u * v.x) + sqr(d.alpha_v * v.y);
  if (dot(v, m) * v.z <= 0.0f) return 0.0f;
  if (xy_alpha_2 == 0.0f) return 1.0f;
  float tan_theta_alpha_2 = xy_alpha_2 / (v.z * v.z);
  if (d.beckmann) {
    float a = 1.0f / sqrt(tan_theta_alpha_2);
    if (a >= 1.6f) return 1.0f;
    return (3.535f * a + 2.181f * a * a) / (1.0f + 2.276f * a + 2.577f * a * a);
  }
  return 2.0f / (1.0f + sqrt(1.0f + tan_theta_alpha_2));
}

INLINE float microfacet_g(Microfacet d, vec3 wi, vec3 wo, vec3 m) {
  return microfacet_smith_g1(d, wi, m) * microfacet_smith_g1(d, wo, m);
}

// Smith's G1 = 1 / (1 + Lambda) without approximation (Heitz 2014, eqs. 72 and 86:
// Lambda = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)) for Beckmann, a = 1 / (alpha tan)):
// the masking that the visible-normal sampler realises. The BSDFs evaluate Mitsuba's G1
// (Walter's rational fit for Beckmann), the densities this one, so that the density of the
// sampled normals integrates to one and equals what the sampler draws.
INLINE float microfacet_smith_g1_exact(Microfacet d, vec3 v, vec3 m) {
  if (!d.beckmann) return microfacet_smith_g1(d, v, m);
  float xy_alpha_2 = sqr(d.alpha_u * v.x) + sqr(d.alpha_v * v.y);
  if (dot(v, m) * v.z <= 0.0f) return 0.0f;
  if (xy_alpha_2 == 0.0f) return 1.0f;
  float a = abs(v.z) / sqrt(xy_alpha_2);
  float lambda = 0.5f * (erf_approx(a) - 1.0f) + exp(-a * a) / (2.0f * a) * INV_SQRT_PI;
  return 1.0f / (1.0f + max(lambda, 0.0f));
}

// Solid-angle density of microfacet_sample: D(m) cos(theta_m), or the distribution of visible
// normals D_wi(m) = G1(wi, m) |wi.m| D(m) / cos(theta_i) (Heitz & d'Eon 2014, eq. 2).
INLINE float microfacet_pdf(Microfacet d, vec3 wi, vec3 m) {
  float result = microfacet_d(d, m);
  if (d.sample_visible) {
    return result * microfacet_smith_g1_exact(d, wi, m) * abs(dot(wi, m)) / wi.z;
  }
  return result * m.z;
}

// Slope (x, y) of a visible normal for the configuration alpha = 1, phi_i = 0.
INLINE vec2 microfacet_sample_visible_11(bool beckmann, float cos_theta_i, vec2 u) {
  if (beckmann) {
    // Heitz & d'Eon 2014, §4.2 / appendix: invert the CDF of the slope x (eq. 14) in the
    // erf domain by Newton steps from the analytic grazing-angle guess, then sample y from
    // the normal distribution.
    float tan_theta_i = safe_sqrt(1.0f - cos_theta_i * cos_theta_i) / cos_theta_i;
    float cot_theta_i = 1.0f / tan_theta_i;
    float maxval = erf_approx(cot_theta_i);
    u = clamp(u, vec2(1e-6f), vec2(1.0f - 1e-6f));
    float x = maxval - (maxval + 1.0f) * erf_approx(sqrt(-log(u.x)));
    float target = u.x * (1.0f + maxval + INV_SQRT_PI * tan_theta_i * exp(-sqr(cot_theta_i)));
    for (int i = 0; i < 3; ++i) {
      float slope = erfinv_approx(x);
      float value = 1.0f + x + INV_SQRT_PI * tan_theta_i * exp(-slope * slope) - target;
      float derivative = 1.0f - slope * tan_theta_i;
      x -= value / derivative;
    }
    return vec2(erfinv_approx(x), erfinv_approx(2.0f * u.y - 1.0f));
  }
  // GGX: Heitz 2018 (Listing 1) — a uniform point on the disk, its upper half squeezed by
  // (1 + cos theta_i) / 2, projected onto the hemisphere, read as a slope of the alpha = 1
  // surface viewed from theta_i.
  vec2 p = square_to_uniform_disk_concentric(u);
  float s = 0.5f * (1.0f + cos_theta_i);
  p.y = mix(safe_sqrt(1.0f - p.x * p.x), p.y, s);
  float z = safe_sqrt(1.0f - dot(p, p));
  float sin_theta_i = safe_sqrt(1.0f - cos_theta_i * cos_theta_i);
  float norm = 1.0f / (sin_theta_i * p.y + cos_theta_i * z);
  return vec2(cos_theta_i * p.y - sin_theta_i * z, p.x) * norm;
}

// Draws a microfacet normal for the direction wi (wi.z > 0); its density is microfacet_pdf.
INLINE vec3 microfacet_sample(Microfacet d, vec3 wi, vec2 u) {
  if (d.sample_visible) {
    // Heitz & d'Eon 2014, §4.1: stretch wi, sample the alpha = 1 slope, rotate, unstretch.
    vec3 wi_p = normalize(vec3(d.alpha_u * wi.x, d.alpha_v * wi.y, wi.z));
    float sin2 = wi_p.x * wi_p.x + wi_p.y * wi_p.y;
    float cos_phi = 1.0f;
    float sin_phi = 0.0f;
    if (sin2 > 0.0f) {
      float inv_sin = 1.0f / sqrt(sin2);
      cos_phi = clamp(wi_p.x * inv_sin, -1.0f, 1.0f);
      sin_phi = clamp(wi_p.y * inv_sin, -1.0f, 1.0f);
    }
    vec2 slope = microfacet_sample_visible_11(d.beckmann, wi_p.z, u);
    vec2 s = vec2((cos_phi * slope.x - sin_phi * slope.y) * d.alpha_u,
                  (sin_phi * slope.x + cos_phi * slope.y) * d.alpha_v);
    return normalize(vec3(-s.x, -s.y, 1.0f));
  }
  // Walter et al. eqs. 28 and 35 (theta_m), with the anisotropic azimuth of Heitz 2014
  // (phi_m = atan(alpha_v / alpha_u tan(2 pi u)), quadrant kept).
  float sin_phi;
  float cos_phi;
  float alpha_2;
  if (d.alpha_u == d.alpha_v) {
    float phi = 2.0f * PI * u.y;
    sin_phi = sin(phi);
    cos_phi = cos(phi);
    alpha_2 = d.alpha_u * d.alpha_u;
  } else {
    float tmp = (d.alpha_v / d.alpha_u) * tan(2.0f * PI * u.y);
    cos_phi = 1.0f / sqrt(tmp * tmp + 1.0f);
    cos_phi = abs(u.y - 0.5f) - 0.25f >= 0.0f ? cos_phi : -cos_phi;
    sin_phi = cos_phi * tmp;
    alpha_2 = 1.0f / (sqr(cos_phi / d.alpha_u) + sqr(sin_phi / d.alpha_v));
  }
  float cos_theta;
  if (d.beckmann) {
    cos_theta = 1.0f / sqrt(1.0f - alpha_2 * log(1.0f - u.x));
  } else {
    float tan_theta_m_2 = alpha_2 * u.x / (1.0f - u.x);
    cos_theta = 1.0f / sqrt(1.0f + tan_theta_m_2);
  }
  float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
  return vec3(cos_phi * sin_theta, sin_phi * sin_theta, cos_theta);
}

TR_NAMESPACE_END

#endif
