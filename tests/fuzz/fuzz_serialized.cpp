// libFuzzer target: a Mitsuba .serialized mesh file, meshes 0 and 1.
#include <exception>

#include "fuzz_input.h"
#include "scenes/serialized.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tr::fuzz::InputFile file(data, size, ".serialized");
  for (std::uint32_t index : {0u, 1u}) {
    try {
      tr::load_serialized_mesh(file.path(), index);
    } catch (const std::exception&) {
    }
  }
  return 0;
}
