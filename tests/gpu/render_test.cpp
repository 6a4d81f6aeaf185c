// The real integrator on the hand-built scene: statistics, progress and value ranges.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_backend/render_gpu.h"
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

}  // namespace
}  // namespace tr
