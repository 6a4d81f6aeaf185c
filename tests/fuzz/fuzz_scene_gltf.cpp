// libFuzzer target: a glTF 2.0 scene (scenes/gltf/), as a .glb when the bytes start with the GLB
// magic "glTF", else as a .gltf. Loading may refuse the input (SceneError) but must never
// crash, hang or read out of bounds: the container, the JSON, buffers and views, accessors
// (strides, sparse substitution), primitives and the node tree are all read from it.
#include <cstring>
#include <exception>

#include "fuzz_input.h"
#include "scenes/load_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  tr::fuzz::InputFile file(data, size, glb ? ".glb" : ".gltf");
  try {
    tr::load_scene(file.path(), {});
  } catch (const std::exception&) {
  }
  return 0;
}
