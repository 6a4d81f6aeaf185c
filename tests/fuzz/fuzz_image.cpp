// libFuzzer target: an image file through the readers of io/image_formats.h and the texel
// conversion, as a bitmap texture or an envmap reads it. The first byte picks the file's
// extension (the readers go by the file's first bytes, not its name) and by its top bit `raw`;
// the rest is the file.
#include <exception>
#include <string>

#include "fuzz_input.h"
#include "scenes/bitmap.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const extensions[] = {".png", ".jpg", ".exr", ".hdr",
                                           ".bmp", ".tga", ".pfm", ".ppm"};
  if (size == 0) return 0;
  tr::fuzz::InputFile file(data + 1, size - 1, extensions[data[0] % 8]);
  try {
    tr::load_image(file.path(), (data[0] & 0x80) != 0);
  } catch (const std::exception&) {
  }
  return 0;
}
