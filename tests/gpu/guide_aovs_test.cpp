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
  test::expect_guide_sphere_render(scene, r);
}

}  // namespace
}  // namespace tr
