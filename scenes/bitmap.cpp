#include "scenes/bitmap.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace tr {

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

namespace {

// Integer samples are sRGB-decoded unless raw; 8-bit data takes only 256 values, decoded once.
class ToLinear {
 public:
  ToLinear(const OIIO::TypeDesc& format, bool raw)
      : decode_(!raw && !format.is_floating_point()),
        eight_bit_(format.basetype == OIIO::TypeDesc::UINT8) {
    for (int i = 0; i < 256; ++i) table_[i] = srgb_to_linear(i / 255.0f);
  }
  glm::vec4 operator()(glm::vec4 t) const {
    if (!decode_) return t;
    return glm::vec4(channel(t.x), channel(t.y), channel(t.z), t.w);
  }

 private:
  float channel(float c) const {
    return eight_bit_ ? table_[std::clamp(int(std::lround(c * 255.0f)), 0, 255)]
                      : srgb_to_linear(c);
  }
  bool decode_;
  bool eight_bit_;
  float table_[256];
};

std::string one_line(std::string message) {
  for (char& c : message)
    if (c == '\n') c = ' ';
  return message;
}

// The header's size is checked before anything is allocated for it: a corrupt or hostile
// header may claim billions of texels in a file of a few bytes.
void check_size(const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw std::runtime_error("image is empty");
  if (image.width > kMaxImageSide || image.height > kMaxImageSide)
    throw std::runtime_error("image of " + std::to_string(image.width) + " x " +
                             std::to_string(image.height) + " texels: twinray reads at most " +
                             std::to_string(kMaxImageSide) + " per side");
  const double bytes = double(image.width) * double(image.height) * sizeof(glm::vec4);
  const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (memory > 0.0 && bytes > memory)
    throw std::runtime_error("image of " + std::to_string(image.width) + " x " +
                             std::to_string(image.height) + " texels needs " +
                             std::to_string(int(std::ceil(bytes / 1073741824.0))) +
                             " GiB, more than this machine's memory");
  if (image.channels < 1 || image.channels > 4)
    throw std::runtime_error("unsupported channel count " + std::to_string(image.channels) +
                             " (expected Y, YA, RGB or RGBA)");
}

// OpenEXR 3.1 allocates what an attribute's size field claims (up to 2 GiB) before it finds that
// the file is shorter, so an EXR header's attribute sizes are checked against the file first.
// Layout (OpenEXR file layout document): magic 20000630, a version word whose bit 12 marks a
// multi-part file, then headers of attributes (name\0 type\0 int32 size, value), each header
// ending with an empty name, and for multi-part files an empty header after the last.
void check_exr_attributes(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  const std::int64_t length = file.tellg();
  file.seekg(0);
  std::uint32_t magic = 0, version = 0;
  if (!file.read(reinterpret_cast<char*>(&magic), 4) || magic != 20000630u) return;
  if (!file.read(reinterpret_cast<char*>(&version), 4)) return;
  const bool multi_part = (version & 0x1000u) != 0;
  auto read_string = [&file](std::string& s) {
    s.clear();
    for (char c; file.get(c) && c != '\0';) s += c;
    return bool(file);
  };
  std::string name, type;
  bool header_empty = true;
  while (read_string(name)) {
    if (name.empty()) {
      if (!multi_part || header_empty) return;
      header_empty = true;
      continue;
    }
    header_empty = false;
    std::int32_t size = 0;
    if (!read_string(type) || !file.read(reinterpret_cast<char*>(&size), 4)) return;
    const std::int64_t left = length - std::int64_t(file.tellg());
    if (size < 0 || size > left)
      throw std::runtime_error("cannot open image: EXR attribute '" + name + "' claims " +
                               std::to_string(size) + " bytes, the file has " +
                               std::to_string(left) + " left");
    file.seekg(size, std::ios::cur);
  }
}

}  // namespace

Image load_image(const std::string& path, bool raw) {
  check_exr_attributes(path);
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error("cannot open image: " + one_line(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.bytes_per_channel = int(spec.format.size());
  check_size(image);

  // Read in bands of rows so that memory grows with the data the file really holds; a tiled
  // file in bands of whole tile rows (OpenImageIO 2.4's read_scanlines fails on tiled files).
  if (spec.depth > 1) throw std::runtime_error("volume images are not textures");
  const ToLinear to_linear(spec.format, raw);
  const int unit = std::clamp(spec.tile_height, 1, image.height);
  const int band = unit * std::max(1, (1 << 20) / (image.width * unit));
  std::vector<float> rows(size_t(image.width) * std::min(band, image.height) * image.channels);
  for (int y0 = 0; y0 < image.height; y0 += band) {
    const int y1 = std::min(image.height, y0 + band);
    const bool read =
        spec.tile_width > 0
            ? in->read_tiles(0, 0, spec.x, spec.x + image.width, spec.y + y0, spec.y + y1, spec.z,
                             spec.z + 1, 0, image.channels, OIIO::TypeDesc::FLOAT, rows.data())
            : in->read_scanlines(0, 0, spec.y + y0, spec.y + y1, 0, 0, image.channels,
                                 OIIO::TypeDesc::FLOAT, rows.data());
    if (!read) throw std::runtime_error("cannot read image: " + one_line(in->geterror()));
    for (size_t i = 0; i < size_t(image.width) * (y1 - y0); ++i) {
      const float* px = &rows[i * image.channels];
      glm::vec4 t = image.channels <= 2
                        ? glm::vec4(px[0], px[0], px[0], image.channels == 2 ? px[1] : 1.0f)
                        : glm::vec4(px[0], px[1], px[2], image.channels == 4 ? px[3] : 1.0f);
      t = to_linear(t);
      if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z))
        throw std::runtime_error("image contains NaN or infinite values");
      image.texels.push_back(t);
    }
  }
  in->close();
  return image;
}

}  // namespace tr
