#include "validation/image/rgb_image.h"

#include <algorithm>
#include <cmath>

namespace tr {

RgbImage to_rgb(const Image& img, const std::string& what) {
  check_image_shape(what, img);
  std::vector<std::string> names =
      img.channel_names.empty() ? default_channel_names(img.channels) : img.channel_names;
  int source[3];
  if (img.channels == 1 || (img.channels == 2 && names[1] == "A")) {
    source[0] = source[1] = source[2] = 0;
  } else {
    const char* wanted[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      auto it = std::find(names.begin(), names.end(), wanted[c]);
      if (it == names.end())
        throw ImageError(what + ": no channel named " + wanted[c] + " (has " +
                         std::to_string(img.channels) + " channels)");
      source[c] = int(it - names.begin());
    }
  }
  RgbImage out;
  out.width = img.width;
  out.height = img.height;
  out.rgb.resize(3 * out.pixel_count());
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) {
        float v = img.at(x, y, source[c]);
        if (!std::isfinite(v))
          throw ImageError(what + ": non-finite value at pixel (" + std::to_string(x) + ", " +
                           std::to_string(y) + ") channel " + names[source[c]]);
        out.at(x, y, c) = v;
      }
  return out;
}

RgbImage read_rgb(const std::string& path) { return to_rgb(read_image(path), path); }

void check_same_size(const RgbImage& a, const std::string& a_name, const RgbImage& b,
                     const std::string& b_name) {
  if (a.width != b.width || a.height != b.height)
    throw ImageError(b_name + ": size " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                     " differs from " + a_name + " (" + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + ")");
}

}  // namespace tr
