// Image files -> linear RGBA texels (io/image_formats.h readers), row-major with the top row first,
// the layout of SceneBuffers::texels and core/texture.h.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tr {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;               // in the file: 1 (Y), 2 (YA), 3 (RGB) or 4 (RGBA)
  int bytes_per_channel = 0;      // of the file's samples: 1 (8-bit), 2 (16-bit, half), 4 (float)
  std::vector<glm::vec4> texels;  // Y is broadcast to RGB; alpha 1 when the file has none
};

// Larger than any texture in practice; a header claiming more is refused before anything is
// allocated for it.
constexpr int kMaxImageSide = 65536;

// Integer-valued images (8/16-bit PNG, JPEG, ...) are sRGB-encoded and decoded to linear
// (IEC 61966-2-1 transfer function) unless `raw`, as Mitsuba's bitmap texture does; float
// images (EXR, HDR) are taken as linear. Throws std::runtime_error with a one-line reason (also for
// more than kMaxImageSide texels a side, or more texels than this machine's memory holds).
Image load_image(const std::string& path, bool raw);

float srgb_to_linear(float c);

}  // namespace tr
