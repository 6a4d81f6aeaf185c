// Linear RGB images in double precision, the common input of every comparison here.
#pragma once

#include <string>
#include <vector>

#include "io/image.h"

namespace tr {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<double> rgb;  // 3 values per pixel, row-major, top row first

  size_t pixel_count() const { return size_t(width) * height; }
  double& at(int x, int y, int c) { return rgb[3 * (size_t(y) * width + x) + c]; }
  double at(int x, int y, int c) const { return rgb[3 * (size_t(y) * width + x) + c]; }
};

// The channels named R, G, B of `img` (any order, other channels ignored), or a single
// luminance channel repeated three times. Throws ImageError("what: ...") otherwise, or when a
// value is NaN or infinite.
RgbImage to_rgb(const Image& img, const std::string& what);

// read_image + to_rgb.
RgbImage read_rgb(const std::string& path);

// Throws ImageError unless a and b have the same size.
void check_same_size(const RgbImage& a, const std::string& a_name, const RgbImage& b,
                     const std::string& b_name);

}  // namespace tr
