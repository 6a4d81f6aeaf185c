// Mitsuba's `aov` integrator on the GPU (lavapipe in CI): the closed-form AOVs of a sphere, every
// AOV channel of validation/mitsuba/plugins/aov.xml against Mitsuba 3.8's reference
// (aov_reference_check.h), CPU <-> GPU lockstep of every AOV channel and the colour at 16 spp
// (same seed: the same camera rays up to float rounding), and the refusal of ray-generation
// shaders without the AOV one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "aov_reference_check.h"
#include "aov_sphere_check.h"
#include "cpu_backend/render_cpu.h"
#include "gpu_backend/gpu_error.h"
#include "gpu_backend/render_gpu.h"

namespace tr {
namespace {

TEST(AovGpu, SphereMatchesClosedForm) {
  Scene scene = load_scene(std::string(TWINRAY_CPU_TEST_SCENES) + "/aov_sphere.xml", {});
  RenderOptions options;
  options.seed = 7;
  RenderResult r = render_gpu(scene, options);
  test::expect_aov_sphere(scene, r, 1e-5);
}

// The AOVs are a ray-generation shader of their own (shaders/aov.rgen); a render whose shaders
// lack it cannot write a scene's AOVs and must say so rather than leave them empty.
TEST(AovGpu, ShadersWithoutTheAovShaderAreRefused) {
  Scene scene = load_scene(std::string(TWINRAY_CPU_TEST_SCENES) + "/aov_sphere.xml", {});
  RaygenShader without_aovs = renderer_raygen();
  without_aovs.aovs.reset();
  EXPECT_THROW(render_with_raygen(scene, RenderOptions(), without_aovs), GpuError);
}

TEST(AovGpu, ChannelsMatchMitsuba) {
  Scene scene = test::load_aov_reference_scene();
  test::expect_aov_channels_match_mitsuba(scene,
                                          render_gpu(scene, test::aov_reference_options(scene)));
}

// Values agree when within 1e-4 relative + 1e-6 absolute (the lockstep tolerance of
// tests/gpu/scene_render_test.cpp); at least 99% of each channel's pixels must. uv is included:
// this scene has no uv seam in view (the spheres' seams face away from the camera).
TEST(AovGpu, LockstepWithCpu) {
  Scene scene = test::load_aov_reference_scene();
  RenderOptions options;
  options.spp = 16;
  options.seed = 5;
  RenderResult gpu = render_gpu(scene, options);
  RenderResult cpu = render_cpu(scene, options);
  ASSERT_EQ(gpu.aov_count, 8u);
  ASSERT_EQ(gpu.aov_mean.size(), cpu.aov_mean.size());
  const size_t pixels = size_t(cpu.width) * cpu.height;
  std::vector<std::pair<std::string, int>> channels = {{"R", 0}, {"G", 1}, {"B", 2}};
  for (size_t a = 0; a < scene.aov_channels.size(); ++a)
    for (size_t c = 0; c < scene.aov_channels[a].size(); ++c)
      channels.push_back({scene.aov_channels[a][c], int(3 + 3 * a + c)});
  for (const auto& [name, index] : channels) {
    size_t agree = 0;
    for (size_t p = 0; p < pixels; ++p) {
      auto value = [&](const RenderResult& r) {
        return index < 3 ? r.mean[3 * p + index] : r.aov_mean[3 * p * r.aov_count + index - 3];
      };
      const double c = value(cpu), g = value(gpu);
      agree += std::abs(g - c) <= 1e-4 * std::abs(c) + 1e-6;
    }
    const double fraction = double(agree) / double(pixels);
    std::printf("%s: %.5f of pixels agree\n", name.c_str(), fraction);
    EXPECT_GE(fraction, 0.99) << name;
  }
}

}  // namespace
}  // namespace tr
