// Rendering loaded scenes on the GPU backend with the validation layer on, and a first
// CPU <-> GPU lockstep check (issue 4, at 1 and 64 spp): same seed and spp, per-value agreement
// within 1e-4 relative + 1e-6 absolute for at least 99% of the values.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../cpu/alpha_test_check.h"
#include "../cpu/ambient_occlusion_check.h"
#include "../cpu/constant_image_check.h"
#include "../cpu/textured_emitter_check.h"
#include "cpu_backend/render_cpu.h"
#include "gpu_backend/render_gpu.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

Scene load(const std::string& path, uint emitter_selection = EMITTER_SELECTION_UNIFORM,
           LoadOptions options = {}) {
  options.emitter_selection = emitter_selection;
  return load_scene(path, options);
}

std::string mitsuba_scene(const std::string& name) {
  return std::string(TWINRAY_SHARED_DIR) + "/mitsuba-tests/tests/scenes/" + name;
}

std::string cpu_test_scene(const std::string& name) {
  return std::string(TWINRAY_CPU_TEST_SCENES) + "/" + name;
}

void expect_lockstep(const std::string& path, uint32_t spp, uint32_t seed,
                     uint emitter_selection = EMITTER_SELECTION_UNIFORM,
                     const LoadOptions& load_options = {}) {
  Scene scene = load(path, emitter_selection, load_options);
  RenderOptions options;
  options.spp = spp;
  options.seed = seed;
  RenderResult gpu = render_gpu(scene, options);
  RenderResult cpu = render_cpu(scene, options);
  ASSERT_EQ(gpu.mean.size(), cpu.mean.size());
  ASSERT_EQ(gpu.stats.samples, cpu.stats.samples);
  size_t agree = 0, worst = 0;
  double worst_excess = -1.0;
  for (size_t i = 0; i < gpu.mean.size(); ++i) {
    const double tolerance = 1e-4 * std::abs(cpu.mean[i]) + 1e-6;
    const double excess = std::abs(gpu.mean[i] - cpu.mean[i]) - tolerance;
    agree += excess <= 0.0;
    if (excess > worst_excess) {
      worst_excess = excess;
      worst = i;
    }
  }
  const double fraction = double(agree) / double(gpu.mean.size());
  const size_t pixel = worst / 3;
  EXPECT_GE(fraction, 0.99) << path << " at " << spp << " spp: " << fraction
                            << " of values agree; worst at pixel (" << pixel % gpu.width << ", "
                            << pixel / gpu.width << ") channel " << worst % 3 << ": gpu "
                            << gpu.mean[worst] << " cpu " << cpu.mean[worst];
  EXPECT_EQ(gpu.stats.rejected_nonfinite, cpu.stats.rejected_nonfinite) << path;
}

TEST(GpuScenes, FloatingSphereRendersWithoutValidationErrors) {
  Scene scene = load(mitsuba_scene("floating_sphere/test_directional_direct.xml"));
  RenderOptions options;
  options.spp = 4;
  uint64_t reported = 0;
  options.progress = [&](uint64_t done, uint64_t total) {
    EXPECT_LE(done, total);
    reported = done;
  };
  RenderResult r = render_gpu(scene, options);
  const size_t pixels = size_t(r.width) * r.height;
  ASSERT_GT(pixels, 0u);
  EXPECT_EQ(r.backend, "gpu");
  EXPECT_EQ(r.stats.samples, 4 * pixels);
  EXPECT_EQ(reported, r.stats.samples);
  EXPECT_GE(r.stats.rays, r.stats.samples);
  size_t lit = 0;
  for (double v : r.mean) {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_GE(v, 0.0);
    lit += v > 0.0;
  }
  EXPECT_GT(lit, 0u);
}

TEST(GpuLockstep, FloatingSphereDirect) {
  expect_lockstep(mitsuba_scene("floating_sphere/test_directional_direct.xml"), 1, 0);
  expect_lockstep(mitsuba_scene("floating_sphere/test_directional_direct.xml"), 64, 3);
}

TEST(GpuLockstep, FurnaceDiffusePath) {
  expect_lockstep(cpu_test_scene("furnace_diffuse_half.xml"), 4, 1);
}

TEST(GpuLockstep, FurnaceDielectricPath) {
  expect_lockstep(cpu_test_scene("furnace_dielectric.xml"), 4, 2);
}

TEST(GpuLockstep, PathLengthWindow) {
  expect_lockstep(cpu_test_scene("path_length_window.xml"), 4, 1);
}

// strict_normals (core/integrator.h, Mitsuba 0.6's strictNormals): tilted shading normals on a
// square under a constant environment, seen from above (light and BSDF samples dropped, rules b
// and c) and from below the face (paths ended at their first hit, rule a); both integrators.
TEST(GpuLockstep, StrictNormals) {
  for (const char* integrator : {"path", "direct"})
    for (const char* origin : {"0, 0, 1", "0.98481, 0, -0.17365"}) {
      LoadOptions load;
      load.defines = {{"integrator", integrator}, {"origin", origin}, {"spp", "16"}};
      expect_lockstep(cpu_test_scene("strict_normals_env.xml"), 16, 1, EMITTER_SELECTION_UNIFORM,
                      load);
    }
}

// vertex_tangents (core/interaction.h tangent_frame, glTF's TANGENT): a normal map under
// bitangents +y and -y, in the shaders as on the CPU.
TEST(GpuLockstep, VertexTangents) {
  for (const char* quad : {"vertex_tangents_quad_b_plus.ply", "vertex_tangents_quad_b_minus.ply"}) {
    LoadOptions load;
    load.defines = {{"quad", quad}};
    expect_lockstep(cpu_test_scene("vertex_tangents.xml"), 4, 1, EMITTER_SELECTION_UNIFORM, load);
  }
}

// The opt-in emitter selections (scenes/emitter_selection.h): the light BVH's descent and
// probabilities, and the power table, in the shaders as on the CPU.
TEST(GpuLockstep, ManyEmittersByLightBvh) {
  expect_lockstep(cpu_test_scene("many_emitters.xml"), 16, 3, EMITTER_SELECTION_BVH);
}

TEST(GpuLockstep, ManyEmittersByPower) {
  expect_lockstep(cpu_test_scene("many_emitters.xml"), 16, 3, EMITTER_SELECTION_POWER);
}

TEST(GpuLockstep, AmbientOcclusionPlanes) {
  expect_lockstep(cpu_test_scene("ambient_occlusion_planes.xml"), 16, 1);
}

// An area emitter of textured radiance (core/emitters/area.h): its light samples and the
// floor's BSDF samples that hit it, in the shaders as on the CPU.
TEST(GpuLockstep, TexturedEmitterFloor) {
  expect_lockstep(cpu_test_scene("textured_emitter_floor.xml"), 16, 1, EMITTER_SELECTION_UNIFORM,
                  test::floor_scene_options());
}

// The same emitter seen head-on, against the closed form of tests/cpu/textured_emitter_test.cpp.
TEST(GpuScenes, TexturedEmitterSeenDirectlyEveryPixelIsItsTexel) {
  Scene scene = load_scene(cpu_test_scene("textured_emitter_view.xml"), test::view_scene_options());
  RenderOptions options;
  options.seed = 2;
  test::expect_texel_view(render_gpu(scene, options), "gpu");
}

// twinray's alphatest through the any-hit shader (shaders/alpha.rahit), as
// tests/cpu/alpha_test_test.cpp on the CPU: camera and shadow rays, then shadow rays alone
// through a cutoff (each render is exact, so this is stronger than a lockstep check; two
// cases only, as each scene compiles its own pipeline on lavapipe).
TEST(GpuScenes, AlphaTestCutsCameraAndShadowRays) {
  struct Case {
    const char* camera_y;
    const char* c0;
    const char* c1;
    const char* cutoff;
    test::AlphaPattern pattern;
  };
  for (Case c : {Case{"5", "0", "1", "0.5", test::AlphaPattern::Checkerboard},
                 Case{"0.5", "0.3", "0.7", "0.5", test::AlphaPattern::Checkerboard}}) {
    LoadOptions load;
    load.defines = {{"camera_y", c.camera_y}, {"c0", c.c0}, {"c1", c.c1}, {"cutoff", c.cutoff}};
    Scene scene = load_scene(cpu_test_scene("alpha_test_plate.xml"), load);
    RenderOptions options;
    options.seed = 7;
    test::expect_alpha_test_image(render_gpu(scene, options), c.pattern,
                                  std::string("gpu camera_y ") + c.camera_y + " opacities " + c.c0 +
                                      "/" + c.c1 + " cutoff " + c.cutoff);
  }
}

// pbrt-v4's ambientocclusion against its closed form between two planes, as
// tests/cpu/ambient_occlusion_test.cpp on the CPU (significance: constant_image_check.h).
TEST(GpuScenes, AmbientOcclusionMatchesTheClosedForm) {
  struct Case {
    const char* cos_sample;
    double max_distance;
    const char* target;
  };
  for (Case c : {Case{"true", 2.0, "0"}, Case{"false", 2.0, "1"}, Case{"true", 0.5, "1"},
                 Case{"false", 0.5, "0"}}) {
    LoadOptions load;
    load.defines = {{"cossample", c.cos_sample},
                    {"maxdistance", std::to_string(c.max_distance)},
                    {"target", c.target}};
    Scene scene = load_scene(cpu_test_scene("ambient_occlusion_planes.xml"), load);
    RenderOptions options;
    options.spp = 256;
    options.seed = 1;
    test::expect_constant_image(render_gpu(scene, options),
                                test::ambient_occlusion_between_planes(1.0, c.max_distance),
                                std::string("gpu cossample ") + c.cos_sample + " maxdistance " +
                                    std::to_string(c.max_distance) + " target " + c.target);
  }
}

}  // namespace
}  // namespace tr
