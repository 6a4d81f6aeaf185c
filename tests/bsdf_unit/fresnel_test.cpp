// Fresnel terms of core/fresnel.h against independent double-precision references.
#include "core/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

namespace tr {
namespace {

// Reflectance of a (possibly absorbing) interface from the complex Fresnel amplitudes
// (Born & Wolf §1.5.2 / §14.2), light arriving from the medium of index 1.
double fresnel_reference(double cos_i, std::complex<double> n) {
  double sin2 = 1.0 - cos_i * cos_i;
  std::complex<double> cos_t = std::sqrt(1.0 - sin2 / (n * n));
  std::complex<double> r_s = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  std::complex<double> r_p = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  return 0.5 * (std::norm(r_s) + std::norm(r_p));
}

TEST(Fresnel, DielectricNormalIncidence) {
  for (float eta : {1.33f, 1.5f, 2.42f, 4.0f}) {
    float expected = ((eta - 1.0f) / (eta + 1.0f)) * ((eta - 1.0f) / (eta + 1.0f));
    EXPECT_NEAR(fresnel_dielectric_reflectance(1.0f, eta), expected, 1e-6f) << eta;
    // Same reflectance from inside at normal incidence.
    EXPECT_NEAR(fresnel_dielectric_reflectance(-1.0f, eta), expected, 1e-6f) << eta;
  }
}

TEST(Fresnel, DielectricMatchesComplexReference) {
  for (float eta : {1.0001f, 1.33f, 1.5f, 2.42f, 4.0f, 1.0f / 1.5f}) {
    for (float cos_i : {1.0f, 0.9f, 0.5f, 0.2f, 0.01f}) {
      double expected = fresnel_reference(cos_i, std::complex<double>(eta, 0.0));
      // Near index matching the amplitudes cancel in float: relative 1e-3.
      EXPECT_NEAR(fresnel_dielectric_reflectance(cos_i, eta), expected, 1e-3 * expected + 2e-6)
          << eta << " " << cos_i;
    }
  }
}

TEST(Fresnel, TotalInternalReflection) {
  float cos_t;
  float eta_it;
  float eta_ti;
  // From inside glass (eta = 1.5), beyond the critical angle asin(1/1.5) = 41.8 degrees.
  float r = fresnel_dielectric(-0.5f, 1.5f, cos_t, eta_it, eta_ti);
  EXPECT_EQ(r, 1.0f);
  EXPECT_EQ(cos_t, 0.0f);
  EXPECT_FLOAT_EQ(eta_it, 1.0f / 1.5f);
  EXPECT_FLOAT_EQ(eta_ti, 1.5f);
  // Just inside the critical angle some light escapes.
  float cos_crit = std::sqrt(1.0f - 1.0f / 2.25f);
  EXPECT_LT(fresnel_dielectric_reflectance(-(cos_crit + 0.01f), 1.5f), 1.0f);
}

TEST(Fresnel, SpecialCases) {
  EXPECT_EQ(fresnel_dielectric_reflectance(0.3f, 1.0f), 0.0f);  // index matched
  EXPECT_EQ(fresnel_dielectric_reflectance(0.0f, 1.5f), 1.0f);  // grazing
}

TEST(Fresnel, RefractionObeysSnell) {
  for (float eta : {1.33f, 1.5f, 1.0f / 1.5f}) {
    for (float cos_i : {0.95f, 0.6f, -0.95f, -0.8f}) {
      vec3 wi = normalize(vec3(std::sqrt(1.0f - cos_i * cos_i), 0.0f, cos_i));
      float cos_t;
      float eta_it;
      float eta_ti;
      float r = fresnel_dielectric(cos_i, eta, cos_t, eta_it, eta_ti);
      if (r >= 1.0f) continue;
      vec3 wt = refract_local(wi, cos_t, eta_ti);
      EXPECT_NEAR(length(wt), 1.0f, 1e-5f);
      EXPECT_LT(wt.z * wi.z, 0.0f);
      // n_i sin_i = n_t sin_t with n_t / n_i = eta_it.
      EXPECT_NEAR(std::sqrt(1.0f - cos_i * cos_i), eta_it * std::sqrt(1.0f - wt.z * wt.z), 1e-5f);
      // Refraction about the macro normal agrees with the general formula.
      vec3 m = vec3(0.0f, 0.0f, 1.0f);
      vec3 wt2 = refract_about(wi, m, cos_t, eta_ti);
      EXPECT_NEAR(distance(wt, wt2), 0.0f, 1e-5f);
    }
  }
}

TEST(Fresnel, ConductorMatchesComplexReference) {
  // Gold-, aluminium- and copper-like RGB indices.
  vec3 eta(0.143f, 1.657f, 0.200f);
  vec3 k(3.983f, 9.224f, 3.912f);
  for (float cos_i : {1.0f, 0.8f, 0.5f, 0.1f, 1e-3f}) {
    vec3 f = fresnel_conductor(cos_i, eta, k);
    for (int c = 0; c < 3; ++c) {
      double expected = fresnel_reference(cos_i, std::complex<double>(eta[c], k[c]));
      EXPECT_NEAR(f[c], expected, 2e-5) << cos_i << " channel " << c;
    }
  }
  // Normal incidence closed form ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
  float n = 0.789f;
  float kk = 6.15f;
  float expected = ((n - 1) * (n - 1) + kk * kk) / ((n + 1) * (n + 1) + kk * kk);
  EXPECT_NEAR(fresnel_conductor(1.0f, vec3(n), vec3(kk)).x, expected, 1e-6f);
}

TEST(Fresnel, ConductorNearIndexMatchIsNonNegative) {
  for (float cos_i = 0.0f; cos_i <= 1.0f; cos_i += 1.0f / 1024.0f) {
    vec3 f = fresnel_conductor(cos_i, vec3(1.0f, 1.0001f, 0.9999f), vec3(0.0f, 1e-4f, 0.0f));
    EXPECT_TRUE(f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f) << cos_i;
    EXPECT_LE(max_component(f), 1.0f) << cos_i;
    // Away from grazing a nearly index-matched surface reflects next to nothing.
    if (cos_i >= 0.5f) {
      EXPECT_LT(max_component(f), 1e-6f) << cos_i;
    }
  }
}

TEST(Fresnel, ConductorDefaultIsPerfectMirror) {
  for (float cos_i : {1.0f, 0.7f, 0.3f, 1e-4f, 0.0f}) {
    vec3 f = fresnel_conductor(cos_i, vec3(0.0f), vec3(1.0f));
    EXPECT_NEAR(f.x, 1.0f, 1e-6f) << cos_i;
  }
}

// F_dr(eta) = 2 \int_0^1 F(mu, eta) mu dmu, by the midpoint rule in double precision.
double diffuse_reflectance_reference(double eta) {
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double mu = (i + 0.5) / n;
    double sin2 = 1.0 - mu * mu;
    double r = 1.0;
    if (sin2 / (eta * eta) < 1.0) r = fresnel_reference(mu, std::complex<double>(eta, 0.0));
    sum += r * mu;
  }
  return 2.0 * sum / n;
}

TEST(Fresnel, DiffuseReflectanceFits) {
  // d'Eon & Irving's fit for eta >= 1 (measured rel. error 0.29% at eta = 4, below 0.1% up
  // to 2), Egan & Hilgeman's for eta < 1 (rel. error <= 0.6% for 1/eta in [1, 2]).
  for (double eta : {1.1, 1.33, 1.5, 2.0}) {
    double ref = diffuse_reflectance_reference(eta);
    EXPECT_NEAR(fresnel_diffuse_reflectance(float(eta)), ref, 0.001 * ref) << eta;
  }
  for (double eta : {4.0}) {
    double ref = diffuse_reflectance_reference(eta);
    EXPECT_NEAR(fresnel_diffuse_reflectance(float(eta)), ref, 0.003 * ref) << eta;
  }
  for (double eta : {1.0 / 1.1, 1.0 / 1.33, 1.0 / 1.5, 1.0 / 1.9}) {
    double ref = diffuse_reflectance_reference(eta);
    EXPECT_NEAR(fresnel_diffuse_reflectance(float(eta)), ref, 0.006 * ref) << eta;
  }
  // Below eta = 0.5 through reciprocity with d'Eon & Irving's fit.
  for (double eta : {1.0 / 2.42, 1.0 / 4.0, 1.0 / 8.0}) {
    double ref = diffuse_reflectance_reference(eta);
    EXPECT_NEAR(fresnel_diffuse_reflectance(float(eta)), ref, 1e-3) << eta;
    EXPECT_LT(fresnel_diffuse_reflectance(float(eta)), 1.0f);
  }
}

}  // namespace
}  // namespace tr
