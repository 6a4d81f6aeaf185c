// Spectrum -> RGB conversion, named IORs.
#include "scenes/spectrum.h"

#include <gtest/gtest.h>

#include "scenes/ior.h"

namespace tr {
namespace {

TEST(Spectrum, MatchingFunctionsInterpolateTheTable) {
  EXPECT_DOUBLE_EQ(cie_xyz(555.0).y, 1.0);  // y-bar peaks at 555 nm (CIE 1931)
  EXPECT_NEAR(cie_xyz(557.5).y, 0.5 * (1.0 + 0.995), 1e-12);
  EXPECT_EQ(cie_xyz(359.0), glm::dvec3(0.0));
  EXPECT_EQ(cie_xyz(831.0), glm::dvec3(0.0));
  EXPECT_NEAR(cie_d65(560.0), 100.0 * CIE_D65_NORMALIZATION, 1e-12);
}

// Reference values from an independent re-implementation (Python, same CIE tables) of
// Mitsuba's procedure: values / 106.75, 1000-point Riemann sum over [360, 830] nm, sRGB matrix.
TEST(Spectrum, EmissionListMatchesMitsubaRgbMode) {
  // The area light of the Mitsuba reference scenes (bsdf_spheres/test_arealight_path.xml).
  glm::dvec3 rgb = spectrum_to_rgb({400, 500, 600, 700}, {0, 8, 15.6, 18.4}, SpectrumUse::Emission);
  EXPECT_NEAR(rgb.x, 20.710837, 2e-5);
  EXPECT_NEAR(rgb.y, 10.854634, 2e-5);
  EXPECT_NEAR(rgb.z, 2.7711518, 2e-5);
}

TEST(Spectrum, ReflectanceListIsD65Weighted) {
  glm::dvec3 rgb =
      spectrum_to_rgb({400, 500, 600, 700}, {.78, .78, .78, .78}, SpectrumUse::Reflectance);
  EXPECT_NEAR(rgb.x, 0.7763668, 2e-6);
  EXPECT_NEAR(rgb.y, 0.7798100, 2e-6);
  EXPECT_NEAR(rgb.z, 0.7760291, 2e-6);
  // A flat spectrum over the whole table is (nearly) white under D65, purple-ish without.
  glm::dvec3 white = spectrum_to_rgb({360, 830}, {1, 1}, SpectrumUse::Reflectance);
  EXPECT_NEAR(white.x, 0.99898536, 1e-6);
  EXPECT_NEAR(white.y, 0.99887370, 1e-6);
  EXPECT_NEAR(white.z, 0.99880154, 1e-6);
  glm::dvec3 e = spectrum_to_rgb({360, 830}, {1, 1}, SpectrumUse::Emission);
  EXPECT_NEAR(e.x, 1.2048837, 1e-6);
  EXPECT_NEAR(e.y, 0.9482282, 1e-6);
  EXPECT_NEAR(e.z, 0.9092668, 1e-6);
}

TEST(Spectrum, ReflectanceIsClampedToUnitRange) {
  glm::dvec3 rgb = spectrum_to_rgb({400, 700}, {2, 2}, SpectrumUse::Reflectance);
  EXPECT_LE(glm::max(rgb.x, glm::max(rgb.y, rgb.z)), 1.0);
  glm::dvec3 unbounded = spectrum_to_rgb({400, 700}, {2, 2}, SpectrumUse::Unbounded);
  EXPECT_GT(unbounded.y, 1.0);
}

TEST(Spectrum, ConstantEmissionIsTheEqualEnergyColor) {
  // Mitsuba v3.2+: value * xyz_to_srgb(1, 1, 1) inside emitters.
  glm::dvec3 e = constant_spectrum_to_rgb(2.0, SpectrumUse::Emission);
  EXPECT_NEAR(e.x, 2 * (3.240479 - 1.537150 - 0.498535), 1e-12);
  EXPECT_NEAR(e.y, 2 * (-0.969256 + 1.875991 + 0.041556), 1e-12);
  EXPECT_NEAR(e.z, 2 * (0.055648 - 0.204043 + 1.057311), 1e-12);
  EXPECT_EQ(constant_spectrum_to_rgb(0.3, SpectrumUse::Reflectance), glm::dvec3(0.3));
}

TEST(Ior, NamedDielectrics) {
  double ior = 0.0;
  ASSERT_TRUE(lookup_dielectric_ior("diamond", ior));
  EXPECT_DOUBLE_EQ(ior, 2.419);
  ASSERT_TRUE(lookup_dielectric_ior("BK7", ior));
  EXPECT_DOUBLE_EQ(ior, 1.5046);
  ASSERT_TRUE(lookup_dielectric_ior("carbon tetrachloride", ior));
  EXPECT_DOUBLE_EQ(ior, 1.461);
  EXPECT_FALSE(lookup_dielectric_ior("unobtainium", ior));
}

TEST(Ior, NamedConductors) {
  const ConductorIor* au = lookup_conductor_ior("Au");
  ASSERT_NE(au, nullptr);
  // Gold: low eta in red, high k in red (its yellow color); cf. pbrt's RGB gold.
  EXPECT_NEAR(au->eta[0], 0.143, 0.01);
  EXPECT_NEAR(au->eta[2], 1.442, 0.01);
  EXPECT_NEAR(au->k[0], 3.983, 0.01);
  EXPECT_EQ(lookup_conductor_ior("none"), nullptr);
  EXPECT_EQ(lookup_conductor_ior("Xx"), nullptr);
  EXPECT_GE(CONDUCTOR_IOR_COUNT, 40);
}

}  // namespace
}  // namespace tr
