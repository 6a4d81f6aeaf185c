// Mitsuba's `aov` integrator on the CPU: closed-form AOVs of a sphere, the colour unchanged by
// the AOVs, and the AOV channels against Mitsuba 3.8's render of validation/mitsuba/plugins.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "aov_sphere_check.h"
#include "io/image.h"
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

// Every AOV channel and R, G, B against Mitsuba 3.8's render of the same scene
// (validation/mitsuba/plugins/aov.xml; refs/aov_mitsuba_1024spp.exr, made by
// `mitsuba -t 1 -m scalar_rgb aov.xml -o aov_mitsuba_1024spp.exr`, Mitsuba's default 1024 spp,
// box filter: a pixel's value is the mean over the pixel). Both renders estimate the same
// pixel means with the same estimator, so each value is judged by twinray's per-sample
// variance v at n = 1024 on both sides: |twinray - Mitsuba| <= 5 sqrt(2 v / n) + 2e-5 max(1,
// |Mitsuba|) (the second term: float rounding, and Mitsuba's RGB constants, 0.8 -> 0.799992).
// Where the channel is constant over the pixel (v = 0: albedo of a plain BSDF, indices,
// background) this is equality to rounding. A pixel that an edge barely crosses can have v = 0
// in one render while the other saw the edge in a sample or two (e.g. albedo 0.05 + 0.75 /
// 1024 at a checker edge): at most 0.5% of the pixels of each channel (20 of 4096) may fail;
// seen over seeds 3, 11-14: at most 8 (albedo), 3 (prim_index, shape_index), 2 elsewhere. A
// wrong value on any object (the smallest covers about 190 pixels) or any systematic offset
// fails far more. Not compared: Mitsuba's image.R/G/B/A, the nested integrator's own channels,
// which twinray does not write (its R, G, B are the same values).
TEST(AovCpu, ChannelsMatchMitsuba) {
  const std::string folder = std::string(TWINRAY_SOURCE_DIR) + "/validation/mitsuba/plugins";
  Scene scene = load_scene(folder + "/aov.xml", {});
  RenderOptions options;
  options.seed = 3;
  RenderResult r = render_cpu(scene, options);
  ASSERT_EQ(r.spp, 1024u);
  Image ref = read_image(folder + "/refs/aov_mitsuba_1024spp.exr");
  ASSERT_EQ(ref.width, int(r.width));
  ASSERT_EQ(ref.height, int(r.height));
  std::map<std::string, int> ref_channel;
  for (int c = 0; c < ref.channels; ++c) ref_channel[ref.channel_names[c]] = c;

  // (name, index into twinray's 3 + 3 * aov_count values per pixel)
  std::vector<std::pair<std::string, int>> channels = {{"R", 0}, {"G", 1}, {"B", 2}};
  for (size_t a = 0; a < scene.aov_channels.size(); ++a)
    for (size_t c = 0; c < scene.aov_channels[a].size(); ++c)
      channels.push_back({scene.aov_channels[a][c], int(3 + 3 * a + c)});
  ASSERT_EQ(channels.size(), 3u + 17u);
  const double n = r.spp;
  int compared = 0;
  for (const auto& [name, index] : channels) {
    ASSERT_TRUE(ref_channel.count(name)) << name << " missing in Mitsuba's EXR";
    int failed = 0;
    for (int y = 0; y < ref.height; ++y)
      for (int x = 0; x < ref.width; ++x) {
        const size_t p = size_t(y) * r.width + x;
        const double value =
            index < 3 ? r.mean[3 * p + index] : r.aov_mean[3 * p * r.aov_count + index - 3];
        const double var =
            index < 3 ? r.variance[3 * p + index] : r.aov_variance[3 * p * r.aov_count + index - 3];
        const double mitsuba = ref.at(x, y, ref_channel[name]);
        const double bound =
            5.0 * std::sqrt(2.0 * var / n) + 2e-5 * std::max(1.0, std::abs(mitsuba));
        ++compared;
        if (std::abs(value - mitsuba) > bound && ++failed <= 3)
          std::printf("%s at (%d, %d): twinray %.9g, Mitsuba %.9g, bound %.3g\n", name.c_str(), x,
                      y, value, mitsuba, bound);
      }
    std::printf("%s: %d of %d pixels outside the bound\n", name.c_str(), failed,
                ref.width * ref.height);
    EXPECT_LE(failed, ref.width * ref.height / 200) << name;
  }
  EXPECT_EQ(compared, 20 * 64 * 64);
}

}  // namespace
}  // namespace tr
