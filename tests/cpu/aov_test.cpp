// Mitsuba's `aov` integrator on the CPU: closed-form AOVs of a sphere (also under a normalmap
// and a blendbsdf), and every AOV channel
// against Mitsuba 3.8's reference of validation/mitsuba/plugins/aov.xml (aov_reference_check.h).
#include <gtest/gtest.h>

#include "aov_reference_check.h"
#include "aov_sphere_check.h"
#include "render_fixture.h"

namespace tr {
namespace {

TEST(AovCpu, SphereMatchesClosedForm) {
  Scene scene = load_scene(test::test_scene("aov_sphere.xml"), {});
  RenderOptions options;
  options.seed = 7;
  RenderResult r = render_cpu(scene, options);
  test::expect_aov_sphere(scene, r, 1e-5);
}

// The albedo through normalmap and blendbsdf (Mitsuba: the nested BSDF's, the weighted mix).
TEST(AovCpu, AlbedoThroughNormalmapAndBlend) {
  Scene scene = load_scene(test::test_scene("aov_sphere_wrapped.xml"), {});
  RenderOptions options;
  options.seed = 7;
  RenderResult r = render_cpu(scene, options);
  test::expect_aov_sphere(scene, r, 1e-5);
}

TEST(AovCpu, ChannelsMatchMitsuba) {
  Scene scene = test::load_aov_reference_scene();
  test::expect_aov_channels_match_mitsuba(scene,
                                          render_cpu(scene, test::aov_reference_options(scene)));
}

}  // namespace
}  // namespace tr
