// The CPU backend's kernels (cpu_backend/cpu_kernels.h): every kernel that covers a scene renders
// it bit for bit as the all-features kernel does, a scene gets the first kernel that covers it,
// and a kernel that does not cover a scene is refused.
#include "cpu_backend/cpu_kernels.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "render_fixture.h"
#include "scenes/scene_features.h"

namespace tr::test {
namespace {

struct KernelScene {
  std::string path;
  std::map<std::string, std::string> defines;
  std::size_t expected_kernel;  // the first kernel that covers it
};

// Between them they reach every kernel first: diffuse only; diffuse, mirror and glass; principled;
// a textured diffuse; Mitsuba's BSDF grid with textures and a mask; textured principled.
std::vector<KernelScene> kernel_scenes() {
  const std::string src = TWINRAY_SOURCE_DIR;
  const std::string spheres = src + "/validation/mitsuba/tests/scenes/bsdf_spheres/";
  return {
      {std::string(TWINRAY_SHARED_DIR) + "/perf/mitsuba-cbox/cbox-rgb.xml", {{"res", "24"}}, 0},
      {src + "/examples/scenes/cornell-box/cornell_box.xml",
       {{"width", "24"}, {"height", "24"}},
       1},
      {src + "/bench/scenes/cornell_principled.xml", {{"width", "24"}, {"height", "24"}}, 2},
      {spheres + "test_textured_diffuse_path.xml", {}, 3},
      {spheres + "test_arealight_path.xml", {}, 4},
      {spheres + "test_texturedprincipled1_path.xml", {}, 5},
  };
}

Scene load(const KernelScene& k) {
  LoadOptions load;
  load.defines = k.defines;
  return load_scene(k.path, load);
}

TEST(CpuKernels, TheLastCoversEveryFeature) {
  EXPECT_TRUE(features_cover(kCpuKernels[kCpuKernelCount - 1].features, all_features()));
  EXPECT_EQ(cpu_kernel_index(all_features()), kCpuKernelCount - 1);
}

TEST(CpuKernels, ASceneGetsTheFirstKernelThatCoversIt) {
  for (const KernelScene& k : kernel_scenes()) {
    Scene scene = load(k);
    EXPECT_EQ(cpu_kernel_index(scene_features(scene.buffers)), k.expected_kernel) << k.path;
  }
}

// 4 spp of each scene with every kernel that covers it, against the all-features kernel.
TEST(CpuKernels, EveryCoveringKernelRendersTheSameImage) {
  std::set<std::size_t> rendered;
  RenderOptions options;
  options.spp = 4;
  options.seed = 3;
  for (const KernelScene& k : kernel_scenes()) {
    Scene scene = load(k);
    const SceneFeatures features = scene_features(scene.buffers);
    CpuTuning all;
    all.kernel = kCpuKernelCount - 1;
    const RenderResult reference = render_cpu(scene, options, all);
    for (std::size_t i = 0; i + 1 < kCpuKernelCount; ++i) {
      if (!features_cover(kCpuKernels[i].features, features)) continue;
      CpuTuning tuning;
      tuning.kernel = i;
      const RenderResult r = render_cpu(scene, options, tuning);
      rendered.insert(i);
      ASSERT_EQ(r.mean.size(), reference.mean.size());
      for (std::size_t v = 0; v < r.mean.size(); ++v) {
        ASSERT_EQ(r.mean[v], reference.mean[v])
            << k.path << " kernel " << kCpuKernels[i].name << " value " << v;
        ASSERT_EQ(r.variance[v], reference.variance[v])
            << k.path << " kernel " << kCpuKernels[i].name << " value " << v;
      }
    }
  }
  EXPECT_EQ(rendered.size(), kCpuKernelCount - 1) << "a kernel no test scene reaches";
}

TEST(CpuKernels, AKernelThatDoesNotCoverTheSceneIsRefused) {
  Scene scene = load(kernel_scenes()[2]);  // principled: not a "diffuse" scene
  CpuTuning tuning;
  tuning.kernel = 0;
  RenderOptions options;
  options.spp = 1;
  EXPECT_THROW(render_cpu(scene, options, tuning), std::invalid_argument);
}

}  // namespace
}  // namespace tr::test
