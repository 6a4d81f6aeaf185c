// libFuzzer target: an image file through OpenImageIO and the texel conversion, as a bitmap
// texture or an envmap reads it. The first byte picks the file's extension (which decides the
// decoder OpenImageIO tries first), the rest is the file.
#include <exception>
#include <string>

#include "fuzz_input.h"
#include "scenes/bitmap.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const extensions[] = {".png", ".jpg", ".exr", ".hdr", ".bmp", ".tga"};
  if (size == 0) return 0;
  tr::fuzz::InputFile file(data + 1, size - 1, extensions[data[0] % 6]);
  try {
    tr::load_image(file.path(), (data[0] & 0x80) != 0);
  } catch (const std::exception&) {
  }
  return 0;
}
