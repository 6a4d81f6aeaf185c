#include "scenes/assimp/assimp_loader.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

namespace tr {

namespace {

// TWINRAY_ASSIMP_MODULE: the module's path in the build tree (scenes/CMakeLists.txt).
ReadGeometryFunction load_module() {
  static ReadGeometryFunction read = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    void* module = dlopen(TWINRAY_ASSIMP_MODULE, RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      failure = dlerror();
      return;
    }
    read = reinterpret_cast<ReadGeometryFunction>(dlsym(module, kReadGeometrySymbol));
    if (!read) failure = dlerror();
  });
  if (!read)
    throw std::runtime_error(std::string("cannot load twinray's Assimp module (") +
                             TWINRAY_ASSIMP_MODULE + "): " + failure);
  return read;
}

}  // namespace

ImportedGeometry read_geometry_with_assimp(const std::string& path) {
  ReadGeometryFunction read = load_module();
  ImportedGeometry geometry;
  std::string error;
  if (!read(path.c_str(), &geometry, &error)) throw std::runtime_error(error);
  return geometry;
}

}  // namespace tr
