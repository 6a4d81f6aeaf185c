// EXR files read through the module that links OpenEXR's C++ library (io/exr_read_module.cpp).
#include <stdexcept>

#include "io/exr_read_module.h"
#include "io/image_formats.h"
#include "io/loadable_module.h"

namespace tr {

// TWINRAY_EXR_READ_MODULE: the module's path in the build tree (io/CMakeLists.txt).
Samples read_exr_samples(const std::string& path, const HeaderCheck& check) {
  static LoadableModule module(TWINRAY_EXR_READ_MODULE, kReadExrSymbol, "EXR reading");
  ReadExrFunction read;
  try {
    read = reinterpret_cast<ReadExrFunction>(module.function());
  } catch (const std::runtime_error& e) {
    fail_image(path, e.what());
  }
  Samples samples;
  std::string error;
  if (!read(path.c_str(), &check, &samples, &error)) fail_image(path, error);
  return samples;
}

}  // namespace tr
