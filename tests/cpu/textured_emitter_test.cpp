// Mitsuba's `area` emitter with a textured radiance (core/emitters/area.h) on the CPU:
//  - seen head-on, every pixel is its texel (textured_emitter_check.h has the closed form);
//  - a second estimator: a diffuse floor under a rectangle of 2 x 2 nearest-filtered radiance
//    (constant columns) renders as under the rectangle's halves as two emitters of constant
//    radiance (other records, other light choices), under Welch's t-tests per pixel and per 4x4
//    block (validation/image, family-wise alpha 1% each, Šidák); and the same test rejects the
//    halves swapped. Ten seeds passed when the test was written.
#include <gtest/gtest.h>

#include <string>

#include "render_fixture.h"
#include "textured_emitter_check.h"
#include "validation/harness/scene_render.h"
#include "validation/image/variance_tests.h"

namespace tr::test {
namespace {

TEST(TexturedEmitter, SeenDirectlyEveryPixelIsItsTexel) {
  RenderOptions options;
  options.seed = 2;
  expect_texel_view(
      render_file(test_scene("textured_emitter_view.xml"), options, view_scene_options()), "cpu");
}

struct WelchResults {
  HypothesisTestResult pixel, block;
};

// The textured light against its halves (`left`, `right`) as two emitters, at 256 spp each.
WelchResults textured_against_split(const glm::vec3& left, const glm::vec3& right, uint seed) {
  RenderOptions options;
  options.seed = seed;
  RenderResult textured =
      render_file(test_scene("textured_emitter_floor.xml"), options, floor_scene_options());
  LoadOptions split;
  split.defines = {{"left", rgb_value(left)}, {"right", rgb_value(right)}};
  options.seed = seed + 1000;
  RenderResult reference =
      render_file(test_scene("textured_emitter_floor_split.xml"), options, split);
  EXPECT_EQ(textured.stats.rejected_nonfinite, 0u);
  RgbImage a = mean_image(textured), av = variance_image(textured);
  RgbImage b = mean_image(reference), bv = variance_image(reference);
  return {pixel_welch_test(a, av, textured.spp, b, bv, reference.spp),
          block_welch_test(a, av, textured.spp, b, bv, reference.spp)};
}

TEST(TexturedEmitter, LightsTheFloorAsItsHalvesAsTwoEmitters) {
  WelchResults r = textured_against_split(kFloorTexels[0], kFloorTexels[1], 7);
  EXPECT_TRUE(r.pixel.passed) << r.pixel.failing_values << " failing values, min p "
                              << r.pixel.min_p << " at (" << r.pixel.min_p_x << ", "
                              << r.pixel.min_p_y << ")";
  EXPECT_TRUE(r.block.passed) << r.block.failing_values << " failing block values, min p "
                              << r.block.min_p << " at (" << r.block.min_p_x << ", "
                              << r.block.min_p_y << ")";
}

// The test can fail: the texture's texels on the wrong halves are rejected.
TEST(TexturedEmitterCatches, HalvesSwappedFail) {
  WelchResults r = textured_against_split(kFloorTexels[1], kFloorTexels[0], 7);
  EXPECT_FALSE(r.pixel.passed);
  EXPECT_FALSE(r.block.passed);
}

}  // namespace
}  // namespace tr::test
