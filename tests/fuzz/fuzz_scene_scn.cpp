// libFuzzer target: a .scn scene (JSON; scenes/scn/). Loading may refuse the input
// (SceneError) but must never crash, hang or read out of bounds.
#include <exception>

#include "fuzz_input.h"
#include "scenes/load_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tr::fuzz::InputFile file(data, size, ".scn");
  try {
    tr::load_scene(file.path(), {});
  } catch (const std::exception&) {
  }
  return 0;
}
