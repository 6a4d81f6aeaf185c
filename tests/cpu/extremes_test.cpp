// Numerical extremes in whole scenes (issue 12), each against its analytic value:
//  - a diffuse plane lit head-on by a directional light (extremes_plane.xml) at scales 1e-4 to
//    1e5, and 1e5 away from the origin: every pixel is rho E / pi. Direct lighting of a plane
//    by a delta light has no noise, so a pixel off by more than 1% is a geometric error: a
//    shadow ray that re-hits the plane it left (acne), a camera ray that misses;
//  - the same plane seen at 60, 85 and 89 degrees from its normal (grazing views);
//  - the same plane under irradiance 1e-6 and 1e8 (float range of the radiance path);
//  - a slab 1e-5 and 1e-7 thin floating 10 thicknesses above the plane (extremes_thin_slab.xml):
//    its top and the plane beside it both rho E cos(30) / pi;
//  - a spherical light of radius 1e-5 (extremes_tiny_light.xml): the image mean against the
//    analytic irradiance of a small sphere, rho L r^2 h / d^3 averaged over the view.
// No sample may be NaN or infinite in any of them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "render_fixture.h"

namespace tr::test {
namespace {

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.9g", v);
  return s;
}

// The camera at `view_angle` (degrees) from the plane's normal, far enough that its whole
// view (half-height 0.5 scale, slanted by the angle) lies in front of it.
RenderResult render_plane(double scale, double offset, double irradiance, double view_angle = 0.0,
                          double plane_scale = 1.0) {
  const double a = view_angle * M_PI / 180.0;
  const double distance = scale * (2.0 + 0.6 * std::tan(a));
  LoadOptions load;
  load.defines = {{"s", number(scale * plane_scale)},
                  {"ox", number(offset)},
                  {"oy", number(-offset)},
                  {"oz", number(offset)},
                  {"E", number(irradiance)},
                  {"half", number(0.5 * scale)},
                  {"cx", number(offset)},
                  {"cy", number(-offset - distance * std::sin(a))},
                  {"cz", number(offset + distance * std::cos(a))},
                  {"near", number(0.5 * scale)},
                  {"far", number(2.0 * distance)}};
  return render_file(test_scene("extremes_plane.xml"), {}, load);
}

void expect_every_pixel(const RenderResult& r, double expected, const std::string& what) {
  EXPECT_EQ(r.stats.rejected_nonfinite, 0u) << what;
  size_t off = 0;
  double worst = expected;
  for (double v : r.mean)
    if (!(std::abs(v - expected) <= 0.01 * expected)) {
      ++off;
      worst = v;
    }
  EXPECT_EQ(off, 0u) << what << ": " << off << " of " << r.mean.size()
                     << " values more than 1% from " << expected << " (e.g. " << worst << ")";
}

class PlaneScale : public testing::TestWithParam<double> {};

TEST_P(PlaneScale, EveryPixelIsRhoEOverPi) {
  const double s = GetParam();
  expect_every_pixel(render_plane(s, 0.0, 1.0), 0.5 / M_PI, "scale " + number(s));
}

INSTANTIATE_TEST_SUITE_P(Extremes, PlaneScale, testing::Values(1e-4, 1e-2, 1.0, 1e2, 1e5));

TEST(Extremes, PlaneFarFromTheOrigin) {
  for (double s : {1.0, 100.0})
    expect_every_pixel(render_plane(s, 1e5, 1.0), 0.5 / M_PI,
                       "scale " + number(s) + " at (1e5, -1e5, 1e5)");
}

TEST(Extremes, GrazingViews) {
  // At 89 degrees the view's footprint on the plane is 1 / cos(89) = 57 times longer: the
  // plane is made 60 times larger. Lambertian radiance does not depend on the view.
  for (double angle : {60.0, 85.0, 89.0})
    expect_every_pixel(render_plane(1.0, 0.0, 1.0, angle, 60.0), 0.5 / M_PI,
                       "view at " + number(angle) + " degrees");
}

TEST(Extremes, TinyAndHugeIrradiance) {
  for (double e : {1e-6, 1e8})
    expect_every_pixel(render_plane(1.0, 0.0, e), 0.5 * e / M_PI, "irradiance " + number(e));
}

TEST(Extremes, RazorThinSlab) {
  // Thickness 1e-5 and 1e-7 at heights 1e-4 and 1e-6 above the plane.
  for (double t : {1e-5, 1e-7}) {
    const double h = 10.0 * t;
    LoadOptions load;
    load.defines = {{"half_t", number(0.5 * t)}, {"center_z", number(h + 0.5 * t)}};
    expect_every_pixel(render_file(test_scene("extremes_thin_slab.xml"), {}, load),
                       0.5 * std::cos(M_PI / 6.0) / M_PI, "slab of thickness " + number(t));
  }
}

TEST(Extremes, LightOfRadiusOneHundredThousandth) {
  const double r = 1e-5, L = 1e10, rho = 0.5;
  LoadOptions load;
  load.defines = {{"r", number(r)}, {"L", number(L)}};
  RenderResult img = render_file(test_scene("extremes_tiny_light.xml"), {}, load);
  EXPECT_EQ(img.stats.rejected_nonfinite, 0u);
  // Radiance at (x, y, 0) from a sphere of radius r << d at height h = 1: rho / pi times the
  // irradiance L pi r^2 (h / d) / d^2 (Lambert's cosine at the plane, solid angle pi r^2 / d^2).
  auto radiance = [&](double x, double y) {
    const double d = std::sqrt(x * x + y * y + 1.0);
    return rho * L * r * r / (d * d * d);
  };
  // Mean over the view [-0.05, 0.05] x [0.45, 0.55], midpoint rule on a fine grid.
  const int n = 400;
  double expected = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      expected += radiance(-0.05 + 0.1 * (i + 0.5) / n, 0.45 + 0.1 * (j + 0.5) / n);
  expected /= double(n) * n;
  double mean = 0.0;
  for (double v : img.mean) mean += v;
  mean /= double(img.mean.size());
  EXPECT_NEAR(mean, expected, 0.01 * expected);
  const double lo = radiance(0.05, 0.55), hi = radiance(0.0, 0.45);
  for (double v : img.mean) {
    EXPECT_GE(v, 0.99 * lo);
    EXPECT_LE(v, 1.01 * hi);
  }
}

}  // namespace
}  // namespace tr::test
