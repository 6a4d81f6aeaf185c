#include "scenes/bitmap.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "io/image_formats.h"
#include "io/temp_file.h"

namespace tr {

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

namespace {

// Integer samples are sRGB-decoded unless raw; 8-bit data takes only 256 values, decoded once.
class ToLinear {
 public:
  ToLinear(const Samples& samples, bool raw)
      : decode_(!raw && !samples.floating),
        eight_bit_(!samples.floating && samples.bytes_per_channel == 1) {
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
  Image image;
  Samples samples;
  try {
    samples = read_samples(path, [&image](int width, int height, int channels) {
      image.width = width;
      image.height = height;
      image.channels = channels;
      check_size(image);
    });
  } catch (const FileError& e) {
    // The readers' ImageError reads "path: reason"; the scene loader names the path itself.
    std::string reason = e.what();
    if (reason.rfind(path + ": ", 0) == 0) reason.erase(0, path.size() + 2);
    throw std::runtime_error("cannot open image: " + reason);
  }
  image.bytes_per_channel = samples.bytes_per_channel;

  const ToLinear to_linear(samples, raw);
  image.texels.reserve(size_t(image.width) * image.height);
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i) {
    const float* px = &samples.values[i * image.channels];
    glm::vec4 t = image.channels <= 2
                      ? glm::vec4(px[0], px[0], px[0], image.channels == 2 ? px[1] : 1.0f)
                      : glm::vec4(px[0], px[1], px[2], image.channels == 4 ? px[3] : 1.0f);
    t = to_linear(t);
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z))
      throw std::runtime_error("image contains NaN or infinite values");
    image.texels.push_back(t);
  }
  return image;
}

}  // namespace tr
