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
#include "scenes/guide_aovs.h"
#include "scenes/scene_features.h"

namespace tr::test {
namespace {

struct KernelScene {
  std::string path;
  std::map<std::string, std::string> defines;
  std::size_t expected_kernel;  // the first kernel that covers it
  std::string guide_aovs;       // --aov's list, or none
};

// Between them they reach every kernel first: diffuse only; diffuse, mirror and glass; principled;
// a textured diffuse; Mitsuba's BSDF grid with textures and a mask; textured principled. The
// last three exercise the rest of what the lean kernels leave out: AOVs, the `direct`
// integrator, and a correlated sampler (`sobol`, two passes of 2 samples: the pass moments).
std::vector<KernelScene> kernel_scenes() {
  const std::string src = TWINRAY_SOURCE_DIR;
  const std::string spheres = src + "/validation/mitsuba/tests/scenes/bsdf_spheres/";
  return {
      {std::string(TWINRAY_SHARED_DIR) + "/perf/mitsuba-cbox/cbox-rgb.xml", {{"res", "24"}}, 0, ""},
      {src + "/examples/scenes/cornell-box/cornell_box.xml",
       {{"width", "24"}, {"height", "24"}},
       1,
       ""},
      {src + "/bench/scenes/cornell_principled.xml", {{"width", "24"}, {"height", "24"}}, 2, ""},
      {spheres + "test_textured_diffuse_path.xml", {}, 3, ""},
      {spheres + "test_arealight_path.xml", {}, 4, ""},
      {spheres + "test_texturedprincipled1_path.xml", {}, 5, ""},
      {std::string(TWINRAY_SHARED_DIR) + "/perf/mitsuba-cbox/cbox-rgb.xml",
       {{"res", "24"}},
       3,
       "albedo,depth,sh_normal"},
      {test_scene("direct_vs_path.xml"), {{"integrator", "direct"}}, 1, ""},
      {test_scene("direct_vs_path.xml"), {{"sampler", "sobol"}, {"spp", "2"}}, 4, ""},
  };
}

Scene load(const KernelScene& k) {
  LoadOptions load;
  load.defines = k.defines;
  if (!k.guide_aovs.empty()) load.guide_aovs = parse_guide_aovs(k.guide_aovs);
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
      const std::string what = k.path + " kernel " + kCpuKernels[i].name;
      ASSERT_EQ(r.mean, reference.mean) << what;
      ASSERT_EQ(r.variance, reference.variance) << what;
      ASSERT_EQ(r.aov_mean, reference.aov_mean) << what;
      ASSERT_EQ(r.aov_variance, reference.aov_variance) << what;
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
