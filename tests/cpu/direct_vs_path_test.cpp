// The `direct` integrator (several emitter and BSDF samples, MIS with sample counts) and the
// `path` integrator at max_depth 2 estimate the same image; Welch's t-tests per pixel and per
// 4x4 block (validation/image, family-wise alpha 1%, Šidák) must not tell them apart.
#include <gtest/gtest.h>

#include "render_fixture.h"
#include "validation/harness/scene_render.h"
#include "validation/image/variance_tests.h"

namespace tr::test {
namespace {

TEST(DirectIntegrator, AgreesWithPathAtDepthTwo) {
  const std::string file = test_scene("direct_vs_path.xml");
  RenderOptions o;
  o.spp = 256;
  o.seed = 11;
  Scene path_scene = load_scene(file, {});
  path_scene.buffers.globals.integrator.max_depth = 2;
  RenderResult path = render_cpu(path_scene, o);
  LoadOptions direct_load;
  direct_load.defines["integrator"] = "direct";
  Scene direct_scene = load_scene(file, direct_load);
  direct_scene.buffers.globals.integrator.emitter_samples = 3;
  direct_scene.buffers.globals.integrator.bsdf_samples = 2;
  o.seed = 12;
  RenderResult direct = render_cpu(direct_scene, o);
  EXPECT_EQ(direct.stats.rejected_nonfinite, 0u);
  RgbImage a = mean_image(path), av = variance_image(path);
  RgbImage b = mean_image(direct), bv = variance_image(direct);
  HypothesisTestResult pixel = pixel_welch_test(a, av, o.spp, b, bv, o.spp);
  HypothesisTestResult block = block_welch_test(a, av, o.spp, b, bv, o.spp);
  EXPECT_TRUE(pixel.passed) << pixel.failing_values << " failing values, min p " << pixel.min_p
                            << " at (" << pixel.min_p_x << ", " << pixel.min_p_y << ")";
  EXPECT_TRUE(block.passed) << block.failing_values << " failing block values, min p "
                            << block.min_p << " at (" << block.min_p_x << ", " << block.min_p_y
                            << ")";
}

}  // namespace
}  // namespace tr::test
