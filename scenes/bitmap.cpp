#include "scenes/bitmap.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tr {

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

Image load_image(const std::string& path, bool raw) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::string error = OIIO::geterror();
    for (char& c : error)
      if (c == '\n') c = ' ';
    throw std::runtime_error("cannot open image: " + error);
  }
  const OIIO::ImageSpec& spec = in->spec();
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.bytes_per_channel = int(spec.format.size());
  if (image.width <= 0 || image.height <= 0) throw std::runtime_error("image is empty");
  if (image.channels < 1 || image.channels > 4)
    throw std::runtime_error("unsupported channel count " + std::to_string(image.channels) +
                             " (expected Y, YA, RGB or RGBA)");
  std::vector<float> data(size_t(image.width) * image.height * image.channels);
  if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, data.data()))
    throw std::runtime_error("cannot read image: " + in->geterror());
  in->close();

  bool decode = !raw && !spec.format.is_floating_point();
  // 8-bit data takes only 256 values: decode them once.
  bool eight_bit = spec.format.basetype == OIIO::TypeDesc::UINT8;
  float table[256];
  for (int i = 0; i < 256; ++i) table[i] = srgb_to_linear(i / 255.0f);
  auto to_linear = [&](float c) {
    return eight_bit ? table[std::clamp(int(std::lround(c * 255.0f)), 0, 255)] : srgb_to_linear(c);
  };
  size_t count = size_t(image.width) * image.height;
  image.texels.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const float* px = &data[i * image.channels];
    glm::vec4 t;
    if (image.channels <= 2) {
      t = glm::vec4(px[0], px[0], px[0], image.channels == 2 ? px[1] : 1.0f);
    } else {
      t = glm::vec4(px[0], px[1], px[2], image.channels == 4 ? px[3] : 1.0f);
    }
    if (decode) t = glm::vec4(to_linear(t.x), to_linear(t.y), to_linear(t.z), t.w);
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z))
      throw std::runtime_error("image contains NaN or infinite values");
    image.texels[i] = t;
  }
  return image;
}

}  // namespace tr
