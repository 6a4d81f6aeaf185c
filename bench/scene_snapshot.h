// A loaded scene written as raw records, so that a benchmark can run on a machine without
// the loader's dependencies (Assimp, OpenImageIO): `bench_snapshot SCENE.xml OUT.twscene`
// here, `bench_gpu_replay OUT.twscene` there. Same-endianness, same-build use only.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace tr {

void write_scene_snapshot(const std::string& path, const Scene& scene);
Scene read_scene_snapshot(const std::string& path);  // throws std::runtime_error

}  // namespace tr
