// Reading geometry through Assimp, whose module (scenes/assimp/assimp_module.cpp) is loaded on
// the first call: processes that import nothing never map Assimp.
#pragma once

#include <string>

#include "scenes/assimp/imported_geometry.h"

namespace tr {

// Throws std::runtime_error with Assimp's message when it cannot read `path`, or naming the
// module and the loader's message when the module cannot be loaded.
ImportedGeometry read_geometry_with_assimp(const std::string& path);

}  // namespace tr
