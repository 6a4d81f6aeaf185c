// The quadratures behind roughplastic's precomputed terms (core/bsdf/roughplastic_table.h).
#include "core/bsdf/roughplastic_table.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tr {
namespace {

TEST(RoughPlasticTable, GaussLegendreIsExactForPolynomials) {
  for (int n : {32, 128}) {
    for (int k = 0; k <= 12; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) {
        float w;
        float x = gauss_legendre_node(n, i, w);
        sum += w * std::pow(double(x), k);
      }
      double exact = (k % 2 == 1) ? 0.0 : 2.0 / (k + 1);
      EXPECT_NEAR(sum, exact, 2e-5) << "n " << n << " degree " << k;
    }
  }
}

TEST(RoughPlasticTable, NearlySmoothInterfaceMatchesFresnel) {
  // With alpha = 1e-3 the rough interface transmits 1 - F(mu) away from grazing angles.
  for (bool beckmann : {false, true}) {
    for (float eta : {1.33f, 1.5f, 2.0f}) {
      for (float mu : {1.0f, 0.7f, 0.4f, 0.2f}) {
        float t = roughplastic_external_transmittance(beckmann, 1e-3f, eta, mu);
        EXPECT_NEAR(t, 1.0f - fresnel_dielectric_reflectance(mu, eta), 2e-3f)
            << beckmann << " " << eta << " " << mu;
      }
      // R_int is the table's cosine-weighted mean of the internal reflectance.
      double expected = 0.0;
      for (uint j = 0; j < ROUGHPLASTIC_TABLE_RES; ++j) {
        float mu = roughplastic_table_mu(j);
        expected += fresnel_dielectric_reflectance(mu, 1.0f / eta) * mu;
      }
      expected *= 2.0 / ROUGHPLASTIC_TABLE_RES;
      EXPECT_NEAR(roughplastic_internal_reflectance(beckmann, 1e-3f, eta), expected, 3e-3)
          << beckmann << " " << eta;
    }
  }
}

TEST(RoughPlasticTable, TransmittancePlusReflectanceAtMostOne) {
  for (bool beckmann : {false, true}) {
    for (float alpha : {0.1f, 0.5f, 1.0f}) {
      for (float mu : {1.0f, 0.5f, 0.1f}) {
        float t = roughplastic_external_transmittance(beckmann, alpha, 1.5f, mu);
        float r = roughplastic_scattered(beckmann, alpha, 1.5f, mu, false);
        EXPECT_GT(t, 0.0f);
        EXPECT_LE(t + r, 1.0f + 1e-5f) << beckmann << " " << alpha << " " << mu;
        // Single scattering loses energy to masking only at grazing or rough settings.
        if (alpha <= 0.1f && mu >= 0.5f) {
          EXPECT_GT(t + r, 0.99f);
        }
      }
    }
  }
}

}  // namespace
}  // namespace tr
