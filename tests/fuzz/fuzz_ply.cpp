// libFuzzer target: a PLY mesh through twinray's reader, as a scene's <shape type="ply">.
#include <exception>

#include "fuzz_input.h"
#include "scenes/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tr::fuzz::InputFile file(data, size, ".ply");
  try {
    tr::load_ply_mesh(file.path(), false);
  } catch (const std::exception&) {
  }
  return 0;
}
