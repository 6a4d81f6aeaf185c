// Synthetic renders for the comparison tests: a reference plus Gaussian noise of the variance a
// Monte Carlo mean of `spp` samples would have, drawn from a fully specified generator
// (std::mt19937_64 with the Box–Muller transform, Box & Muller 1958) so results do not depend
// on the standard library.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "validation/image/rgb_image.h"

namespace tr::testing {

inline std::string shared_dir() { return TWINRAY_SHARED_DIR; }

inline std::string arealight_refs() {
  return shared_dir() + "/mitsuba-tests/tests/scenes/bsdf_spheres/refs/test_arealight_ref_rgb";
}

// Standard normal deviates by Box–Muller.
class Gaussian {
 public:
  explicit Gaussian(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    const double two_pi = 6.283185307179586;
    double u1 = (double(rng_() >> 11) + 0.5) * 0x1.0p-53;  // in (0, 1)
    double u2 = double(rng_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(two_pi * u2);
  }

 private:
  std::mt19937_64 rng_;
};

// reference + N(0, variance / spp) independently per pixel and channel. Variance images
// computed as E[x²] - E[x]² hold tiny negative values from rounding; those count as 0.
inline RgbImage noisy_render(const RgbImage& reference, const RgbImage& variance, double spp,
                             std::uint64_t seed) {
  Gaussian normal(seed);
  RgbImage out = reference;
  for (size_t i = 0; i < out.rgb.size(); ++i)
    out.rgb[i] += std::sqrt(std::max(variance.rgb[i], 0.0) / spp) * normal();
  return out;
}

// Scales the 4x4 block at (x0, y0): pixels with x + y even by `even`, the others by `odd`.
inline void scale_block(RgbImage& img, int x0, int y0, double even, double odd) {
  for (int y = y0; y < y0 + 4; ++y)
    for (int x = x0; x < x0 + 4; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) *= (x + y) % 2 ? odd : even;
}

inline RgbImage constant_image(int width, int height, double r, double g, double b) {
  RgbImage img;
  img.width = width;
  img.height = height;
  for (int i = 0; i < width * height; ++i) img.rgb.insert(img.rgb.end(), {r, g, b});
  return img;
}

}  // namespace tr::testing
