#include "scenes/assimp/assimp_loader.h"

#include <stdexcept>

#include "io/loadable_module.h"

namespace tr {

// TWINRAY_ASSIMP_MODULE: the module's path in the build tree (scenes/CMakeLists.txt).
ImportedGeometry read_geometry_with_assimp(const std::string& path) {
  static LoadableModule module(TWINRAY_ASSIMP_MODULE, kReadGeometrySymbol, "Assimp");
  auto read = reinterpret_cast<ReadGeometryFunction>(module.function());
  ImportedGeometry geometry;
  std::string error;
  if (!read(path.c_str(), &geometry, &error)) throw std::runtime_error(error);
  return geometry;
}

}  // namespace tr
