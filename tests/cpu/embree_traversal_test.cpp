// <scene> embree_use_robust_intersections (Scene::robust_intersections): false reaches Embree
// (another triangle test, so some pixels change, and the summary says so) and renders the same
// image statistically. Significance: each channel's image mean within 3 standard errors of the
// difference (two-sided, 0.27% false-failure rate; the two renders share their random numbers,
// so the test is conservative).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "render_fixture.h"

namespace tr::test {
namespace {

TEST(EmbreeTraversal, NonRobustTraversalRendersTheSameImage) {
  LoadOptions load;
  load.defines = {{"res", "64"}, {"spp", "64"}};
  Scene scene =
      load_scene(std::string(TWINRAY_SHARED_DIR) + "/perf/mitsuba-cbox/cbox-rgb.xml", load);
  ASSERT_TRUE(scene.robust_intersections);
  RenderOptions options;
  options.threads = 2;
  EXPECT_EQ(make_cpu_renderer(scene, options, {})->device().find("not robust"), std::string::npos);
  RenderResult robust = render_cpu(scene, options);

  scene.robust_intersections = false;
  EXPECT_NE(make_cpu_renderer(scene, options, {})->device().find("traversal not robust"),
            std::string::npos);
  RenderResult fast = render_cpu(scene, options);

  ASSERT_EQ(robust.mean.size(), fast.mean.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < robust.mean.size(); ++i) differing += robust.mean[i] != fast.mean[i];
  EXPECT_GT(differing, 0u) << "the flag did not change Embree's traversal";
  const std::size_t pixels = robust.mean.size() / 3;
  for (int c = 0; c < 3; ++c) {
    double sum_robust = 0.0, sum_fast = 0.0, var = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
      sum_robust += robust.mean[3 * p + c];
      sum_fast += fast.mean[3 * p + c];
      var += (robust.variance[3 * p + c] + fast.variance[3 * p + c]) / robust.spp;
    }
    const double difference = (sum_robust - sum_fast) / double(pixels);
    const double se = std::sqrt(var) / double(pixels);
    EXPECT_LE(std::abs(difference), 3.0 * se) << "channel " << c;
  }
}

}  // namespace
}  // namespace tr::test
