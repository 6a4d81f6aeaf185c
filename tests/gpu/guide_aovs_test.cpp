// `--aov` guide buffers (LoadOptions::guide_aovs) on the GPU (lavapipe in CI): the wrapped
// sphere scene's albedo, shading normal and depth against the closed form
// (tests/cpu/guide_aovs_check.h). One render: lavapipe's pipeline build dominates its time.
#include <gtest/gtest.h>

#include <string>

#include "gpu_backend/render_gpu.h"
#include "guide_aovs_check.h"

namespace tr {
namespace {

const std::string kScene = std::string(TWINRAY_CPU_TEST_SCENES) + "/guide_sphere.xml";

TEST(GuideAovsGpu, SphereMatchesClosedForm) {
  LoadOptions load;
  load.guide_aovs = parse_guide_aovs("albedo,sh_normal,depth");
  Scene scene = load_scene(kScene, load);
  RenderOptions options;
  options.seed = 7;
  RenderResult r = render_gpu(scene, options);
  ASSERT_EQ(r.aov_count, 3u);
  ASSERT_EQ(r.spp, 1u);
  test::expect_guide_sphere(
      scene, r.seed,
      [&](uint x, uint y, int g, int c) {
        return r.aov_mean[3 * ((size_t(y) * r.width + x) * 3 + g) + c];
      },
      1e-5);
}

}  // namespace
}  // namespace tr
