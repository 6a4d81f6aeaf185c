// libFuzzer target: a Wavefront OBJ mesh through Assimp, as a scene's <shape type="obj">.
#include <exception>

#include "fuzz_input.h"
#include "scenes/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tr::fuzz::InputFile file(data, size, ".obj");
  try {
    tr::load_mesh_file(file.path(), false);
  } catch (const std::exception&) {
  }
  return 0;
}
