// libFuzzer target: a Wavefront OBJ mesh through twinray's reader, as a scene's <shape type="obj">.
#include <exception>

#include "fuzz_input.h"
#include "scenes/obj_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tr::fuzz::InputFile file(data, size, ".obj");
  try {
    tr::read_obj_file(file.path(), true, false);
  } catch (const std::exception&) {
  }
  return 0;
}
