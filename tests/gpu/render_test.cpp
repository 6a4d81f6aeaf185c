// The real integrator on the hand-built scene: statistics, progress and value ranges.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_backend/gpu_error.h"
#include "gpu_backend/render_gpu.h"
#include "scenes/scene_features.h"
#include "test_scene.h"

namespace tr {
namespace {

TEST(GpuRender, ProbeSceneUnderConstantEnvironment) {
  const uint width = 32, height = 24, spp = 8;
  Scene scene = test::probe_scene(width, height);
  RenderOptions options;
  options.spp = spp;
  options.seed = 5;
  uint64_t reported = 0;
  options.progress = [&](uint64_t done, uint64_t total) {
    EXPECT_EQ(total, uint64_t(spp) * width * height);
    EXPECT_GT(done, reported);
    reported = done;
  };
  RenderResult r = render_gpu(scene, options);
  const size_t pixels = size_t(width) * height;
  EXPECT_EQ(r.backend, "gpu");
  EXPECT_EQ(r.spp, spp);
  EXPECT_EQ(r.seed, 5u);
  EXPECT_EQ(r.stats.samples, spp * pixels);
  EXPECT_EQ(reported, r.stats.samples);
  EXPECT_EQ(r.stats.rejected_nonfinite, 0u);
  // Every camera ray hits (the quad fills the view) and depth 1 samples the environment.
  EXPECT_GE(r.stats.rays, 2 * r.stats.samples);
  ASSERT_EQ(r.mean.size(), 3 * pixels);
  ASSERT_EQ(r.variance.size(), 3 * pixels);
  // Albedo 0.5 under radiance 1 with depth <= 4: every value lies in (0, 0.5 + 0.25 + ...) < 1.
  for (size_t i = 0; i < r.mean.size(); ++i) {
    ASSERT_GT(r.mean[i], 0.0) << i;
    ASSERT_LT(r.mean[i], 1.0) << i;
    ASSERT_GE(r.variance[i], 0.0) << i;
  }
}

// The batch schedule depends on the device type and image size only, so two renders with the
// same seed are bit-identical, over several batches (768 pixels: 256 spp per batch on lavapipe,
// 600 spp = 256 + 256 + 88) and across the float-to-double batch merges.
TEST(GpuRender, SameSeedGivesTheSameImageOnEveryRun) {
  Scene scene = test::probe_scene(32, 24);
  RenderOptions options;
  options.spp = 600;
  options.seed = 9;
  RenderResult a = render_gpu(scene, options);
  RenderResult b = render_gpu(scene, options);
  ASSERT_EQ(a.mean.size(), b.mean.size());
  for (size_t i = 0; i < a.mean.size(); ++i) {
    ASSERT_EQ(a.mean[i], b.mean[i]) << i;
    ASSERT_EQ(a.variance[i], b.variance[i]) << i;
  }
  EXPECT_EQ(a.stats.rays, b.stats.rays);
}

// A pipeline compiled for fewer features than the scene has would drop code the scene needs:
// GpuTuning::features must cover the scene's, or the render fails before compiling.
TEST(GpuRender, PipelineFeaturesMustCoverTheScene) {
  Scene scene = test::probe_scene(8, 8);
  RenderOptions options;
  options.spp = 1;
  GpuTuning tuning;
  tuning.features = scene_features(scene.buffers);
  tuning.features->bsdf_types = 0u;
  EXPECT_THROW(render_with_raygen(scene, options, renderer_raygen(), tuning), GpuError);
}

}  // namespace
}  // namespace tr
