// Every Mitsuba reference scene and the default Cornell box load, with the values they imply.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/material_slots.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

const std::string SHARED = TWINRAY_SHARED_DIR;
const std::string SOURCE = TWINRAY_SOURCE_DIR;

std::vector<std::string> mitsuba_test_scenes(const fs::path& root) {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(root / "tests" / "scenes")) {
    std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.rfind("test_", 0) == 0 && e.path().extension() == ".xml")
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void expect_all_load(const std::vector<std::string>& files) {
  for (const std::string& f : files) {
    SCOPED_TRACE(f);
    Scene s;
    ASSERT_NO_THROW(s = load_scene(f, {})) << f;
    EXPECT_EQ(s.buffers.globals.camera.width, 48u);
    EXPECT_EQ(s.buffers.globals.camera.height, 48u);
    EXPECT_GT(s.buffers.globals.emitter_count, 0u);
    EXPECT_GT(s.buffers.shapes.size(), 0u);
    EXPECT_EQ(s.buffers.instances.size(), 1u);
    EXPECT_EQ(s.integrator_name.rfind("moment(", 0), 0u) << s.integrator_name;
  }
}

// The project's own copy (validation/mitsuba/, self-contained) ...
TEST(LoadMitsubaScenes, ProjectCopyLoads) {
  std::vector<std::string> files = mitsuba_test_scenes(fs::path(SOURCE) / "validation" / "mitsuba");
  ASSERT_EQ(files.size(), 8u);
  expect_all_load(files);
}

// ... and the shared originals, where this checkout has them beside it.
TEST(LoadMitsubaScenes, SharedOriginalsLoad) {
  fs::path root = fs::path(SHARED) / "mitsuba-tests";
  if (!fs::exists(root)) GTEST_SKIP() << root << " is not present";
  std::vector<std::string> files = mitsuba_test_scenes(root);
  ASSERT_EQ(files.size(), 8u);
  expect_all_load(files);
}

// Values the reference scenes imply, as Mitsuba 3 computes them.
TEST(LoadMitsubaScenes, ArealightSceneValues) {
  Scene s = load_scene(
      SOURCE + "/validation/mitsuba/tests/scenes/bsdf_spheres/test_arealight_path.xml", {});
  const SceneBuffers& b = s.buffers;
  EXPECT_EQ(s.spp, 128u);
  EXPECT_EQ(s.integrator_name, "moment(path)");
  EXPECT_EQ(b.globals.integrator.max_depth, 2);
  // Default perspective sensor: 50 mm lens along the diagonal of a square film.
  EXPECT_NEAR(b.globals.camera.half_extent.x, 0.3059412, 1e-6);
  EXPECT_FLOAT_EQ(b.globals.camera.near_clip, 1.0f);
  ASSERT_EQ(b.emitters.size(), 1u);
  // Spectral area light 400:0, 500:8, 600:15.6, 700:18.4 in Mitsuba's RGB mode.
  EXPECT_NEAR(b.emitters[0].radiance.x, 20.710837, 1e-4);
  EXPECT_NEAR(b.emitters[0].radiance.y, 10.854634, 1e-4);
  EXPECT_NEAR(b.emitters[0].radiance.z, 2.7711518, 1e-4);
  // Rectangle light: rotate 120 deg about y, scale 2, translate: area 4 * 4.
  EXPECT_NEAR(b.shapes[b.emitters[0].shape].area, 16.0, 1e-4);
  bool diamond = false;
  for (const Material& m : b.materials)
    diamond |= m.type == BSDF_DIELECTRIC && std::abs(m.eta - 2.419f / 1.000277f) < 1e-6f;
  EXPECT_TRUE(diamond);
}

// Mitsuba's canonical Cornell box, exactly as shipped: its area emitter is declared after the
// shapes that <ref> it, its perspective sensor sets near/far clip and focus_distance.
TEST(LoadMitsubaScenes, MitsubaCornellBoxLoadsUnchanged) {
  fs::path file = fs::path(SHARED) / "perf" / "mitsuba-cbox" / "cbox-rgb.xml";
  ASSERT_TRUE(fs::exists(file)) << file << " is missing: the Mitsuba Cornell box ships in shared/";
  LoadOptions options;
  options.defines["res"] = "64";
  Scene s = load_scene(file.string(), options);
  const SceneBuffers& b = s.buffers;
  EXPECT_EQ(s.spp, 256u);
  EXPECT_EQ(s.integrator_name, "path");
  EXPECT_EQ(b.globals.integrator.max_depth, 6);
  EXPECT_EQ(b.globals.camera.width, 64u);
  EXPECT_FLOAT_EQ(b.globals.camera.near_clip, 10.0f);
  EXPECT_FLOAT_EQ(b.globals.camera.far_clip, 2800.0f);
  // fov 39.3077 degrees along the smaller axis of a square film.
  EXPECT_NEAR(b.globals.camera.half_extent.x, std::tan(39.3077 * M_PI / 360.0), 1e-6);
  ASSERT_EQ(b.emitters.size(), 1u);
  EXPECT_EQ(b.emitters[0].type, EMITTER_AREA);
  EXPECT_EQ(b.emitters[0].radiance, vec3(18.387f, 10.9873f, 2.75357f));
  EXPECT_EQ(b.shapes.size(), 8u);
}

}  // namespace
}  // namespace tr
