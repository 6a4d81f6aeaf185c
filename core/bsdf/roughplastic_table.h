// The two precomputed quantities of Mitsuba 3's `roughplastic` (RoughPlastic::
// parameters_changed with eval_transmittance / eval_reflectance of microfacet.h), computed
// the same way: Gauss-Legendre quadrature over the unit square of visible-normal samples.
//   roughplastic_external_transmittance(mu): fraction of light arriving at cos theta = mu
//     that refracts through the rough interface into the layer,
//       T(mu) = \int G1(wo, h) (1 - F(wi.h)) dD_wi(h),  wo the refraction of wi about h;
//   roughplastic_internal_reflectance: 2 * mean over the table's mu_j of mu_j R(mu_j), R the
//     reflectance of the interface seen from inside (relative IOR 1 / eta), a cosine-weighted
//     hemispherical average.
// The loader evaluates these once per (distribution, alpha, eta), the table's entries and the
// internal reflectance's terms in parallel, and stores the table in a one-row texture
// (core/bsdf/roughplastic.h). Everything is polyglot so both backends could
// rebuild it; the shaders only read the stored values.
#ifndef TWINRAY_CORE_BSDF_ROUGHPLASTIC_TABLE_H
#define TWINRAY_CORE_BSDF_ROUGHPLASTIC_TABLE_H

#include "core/fresnel.h"
#include "core/microfacet.h"

TR_NAMESPACE_BEGIN

// Resolution of the transmittance table, entries at mu_j = max(1e-6, j / (RES - 1))
// (Mitsuba's MI_ROUGH_TRANSMITTANCE_RES).
const uint ROUGHPLASTIC_TABLE_RES = 64u;

INLINE float roughplastic_table_mu(uint j) {
  return max(1e-6f, float(j) / float(ROUGHPLASTIC_TABLE_RES - 1u));
}

// Legendre polynomial P_n(x) and its derivative by the three-term recurrence
// (Abramowitz & Stegun 22.7.10, 22.8.5).
INLINE float legendre_p(int n, float x, OUT(float) derivative) {
  float p_prev = 1.0f;
  float p = x;
  for (int k = 2; k <= n; ++k) {
    float p_next = (float(2 * k - 1) * x * p - float(k - 1) * p_prev) / float(k);
    p_prev = p;
    p = p_next;
  }
  derivative = float(n) * (x * p - p_prev) / (x * x - 1.0f);
  return p;
}

// Node i (ascending) and weight of the n-point Gauss-Legendre rule on [-1, 1]: Newton's
// method on P_n from the Chebyshev guess -cos((2i + 1) pi / (2n)) (Press et al., Numerical
// Recipes §4.5, gauleg), weight 2 / ((1 - x^2) P_n'(x)^2).
INLINE float gauss_legendre_node(int n, int i, OUT(float) weight) {
  float x = -cos(float(2 * i + 1) / float(2 * n) * PI);
  float dp = 1.0f;
  for (int it = 0; it < 8; ++it) {
    float p = legendre_p(n, x, dp);
    x -= p / dp;
  }
  legendre_p(n, x, dp);
  weight = 2.0f / ((1.0f - x * x) * dp * dp);
  return x;
}

// Mitsuba uses 32 nodes per axis for eta > 1 and 128 otherwise.
const int ROUGHPLASTIC_MAX_ORDER = 128;
INLINE int roughplastic_quadrature_order(float eta) { return eta > 1.0f ? 32 : 128; }

// Tensor-product Gauss-Legendre quadrature over [0, 1]^2 of the light that leaves the rough
// interface toward the other side (transmit = true: refraction weighted by 1 - F) or back
// toward wi's side (reflection weighted by F), each masked by G1(wo, h), for visible normals
// h sampled at the quadrature nodes (Mitsuba's eval_transmittance / eval_reflectance).
INLINE float roughplastic_scattered(bool beckmann, float alpha, float eta, float mu,
                                    bool transmit) {
  Microfacet d = microfacet_make(beckmann, alpha, alpha, true);
  vec3 wi = vec3(sqrt(1.0f - mu * mu), 0.0f, mu);
  int n = roughplastic_quadrature_order(eta);
  float nodes[ROUGHPLASTIC_MAX_ORDER];
  float weights[ROUGHPLASTIC_MAX_ORDER];
  for (int i = 0; i < n; ++i) {
    float w;
    nodes[i] = gauss_legendre_node(n, i, w);
    weights[i] = w;
  }
  float result = 0.0f;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      vec2 u = vec2(nodes[i], nodes[j]) * 0.5f + vec2(0.5f);
      vec3 h = microfacet_sample(d, wi, u);
      float cos_t;
      float eta_it;
      float eta_ti;
      float f = fresnel_dielectric(dot(wi, h), eta, cos_t, eta_it, eta_ti);
      float g;
      if (transmit) {
        vec3 wo = refract_about(wi, h, cos_t, eta_ti);
        g = wo.z * wi.z < 0.0f ? microfacet_smith_g1(d, wo, h) * (1.0f - f) : 0.0f;
      } else {
        vec3 wo = reflect_about(wi, h);
        g = wo.z > 0.0f && wi.z > 0.0f ? microfacet_smith_g1(d, wo, h) * f : 0.0f;
      }
      result += g * weights[i] * weights[j];
    }
  }
  return result * 0.25f;
}

INLINE float roughplastic_external_transmittance(bool beckmann, float alpha, float eta, float mu) {
  return roughplastic_scattered(beckmann, alpha, eta, mu, true);
}

// Term j of the internal reflectance's mean: mu_j R(mu_j).
INLINE float roughplastic_internal_term(bool beckmann, float alpha, float eta, uint j) {
  float mu = roughplastic_table_mu(j);
  return roughplastic_scattered(beckmann, alpha, 1.0f / eta, mu, false) * mu;
}

// The internal reflectance from its terms j = 0 .. RES - 1, summed in that order.
INLINE float roughplastic_internal_reflectance_of(float terms[ROUGHPLASTIC_TABLE_RES]) {
  float sum = 0.0f;
  for (uint j = 0u; j < ROUGHPLASTIC_TABLE_RES; ++j) sum += terms[j];
  return 2.0f * sum / float(ROUGHPLASTIC_TABLE_RES);
}

INLINE float roughplastic_internal_reflectance(bool beckmann, float alpha, float eta) {
  float terms[ROUGHPLASTIC_TABLE_RES];
  for (uint j = 0u; j < ROUGHPLASTIC_TABLE_RES; ++j)
    terms[j] = roughplastic_internal_term(beckmann, alpha, eta, j);
  return roughplastic_internal_reflectance_of(terms);
}

TR_NAMESPACE_END

#endif
