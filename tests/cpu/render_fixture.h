// Loads a scene file and renders it on the CPU backend, for the tests of this folder.
#pragma once

#include <string>

#include "cpu_backend/render_cpu.h"
#include "scenes/load_scene.h"

namespace tr::test {

inline std::string test_scene(const std::string& name) {
  return std::string(TWINRAY_TEST_SCENES) + "/" + name;
}

inline RenderResult render_file(const std::string& path, RenderOptions options = {},
                                LoadOptions load = {}) {
  Scene scene = load_scene(path, load);
  return render_cpu(scene, options);
}

}  // namespace tr::test
