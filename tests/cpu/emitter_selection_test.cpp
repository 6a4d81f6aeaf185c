// The opt-in emitter selections (scenes/emitter_selection.h) change the noise, not the image:
// on a scene of many emitters of every kind, renders that choose emitters by power and by the
// light BVH agree with Mitsuba's choice by sampling_weight under Welch's t-tests per pixel and
// per 4x4 block (validation/image, family-wise alpha 1% each, Šidák).
#include "scenes/emitter_selection.h"

#include <gtest/gtest.h>

#include "render_fixture.h"
#include "validation/harness/scene_render.h"
#include "validation/image/variance_tests.h"

namespace tr::test {
namespace {

RenderResult render_with(uint selection, uint spp, uint seed) {
  LoadOptions load;
  load.emitter_selection = selection;
  Scene scene = load_scene(test_scene("many_emitters.xml"), load);
  RenderOptions o;
  o.spp = spp;
  o.seed = seed;
  return render_cpu(scene, o);
}

void expect_same_image(uint selection, uint seed) {
  const uint spp = 256;
  RenderResult reference = render_with(EMITTER_SELECTION_UNIFORM, spp, seed);
  RenderResult test = render_with(selection, spp, seed + 1000);
  EXPECT_EQ(test.stats.rejected_nonfinite, 0u);
  RgbImage a = mean_image(test), av = variance_image(test);
  RgbImage b = mean_image(reference), bv = variance_image(reference);
  HypothesisTestResult pixel = pixel_welch_test(a, av, spp, b, bv, spp);
  HypothesisTestResult block = block_welch_test(a, av, spp, b, bv, spp);
  const char* name = emitter_selection_name(selection);
  EXPECT_TRUE(pixel.passed) << name << ": " << pixel.failing_values << " failing values, min p "
                            << pixel.min_p << " at (" << pixel.min_p_x << ", " << pixel.min_p_y
                            << ")";
  EXPECT_TRUE(block.passed) << name << ": " << block.failing_values
                            << " failing block values, min p " << block.min_p << " at ("
                            << block.min_p_x << ", " << block.min_p_y << ")";
}

TEST(EmitterSelection, ByPowerRendersTheSameImage) {
  expect_same_image(EMITTER_SELECTION_POWER, 3);
}

TEST(EmitterSelection, ByLightBvhRendersTheSameImage) {
  expect_same_image(EMITTER_SELECTION_BVH, 5);
}

}  // namespace
}  // namespace tr::test
