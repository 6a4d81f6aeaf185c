// Scratch scene files for the loader tests: each test writes its XML (and meshes) into a
// fresh folder under the GoogleTest temp dir.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scenes/load_scene.h"

namespace tr::testing_files {

inline std::filesystem::path fresh_dir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "twinray_scene_tests" /
                              (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string write_file(const std::filesystem::path& dir, const std::string& name,
                              const std::string& text) {
  std::filesystem::path p = dir / name;
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << text;
  return p.string();
}

// A minimal valid scene around `body` (a sensor is mandatory).
inline std::string scene_xml(const std::string& body) {
  return "<scene version=\"3.0.0\">\n"
         "  <sensor type=\"perspective\">\n"
         "    <film type=\"hdrfilm\"><integer name=\"width\" value=\"8\"/>"
         "<integer name=\"height\" value=\"8\"/></film>\n"
         "  </sensor>\n" +
         body + "\n</scene>\n";
}

// Loads `path`: true when it loads, false when it fails with a one-line SceneError that names
// the file (any other outcome fails the test).
inline bool loads_or_fails_cleanly(const std::string& path) {
  try {
    load_scene(path, {});
    return true;
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.rfind(path + ":", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return false;
  }
}

const char* const QUAD_OBJ =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";

}  // namespace tr::testing_files
