// The sRGB transfer function, IEC 61966-2-1:1999 §5.2 (encoding) and §5.3 (decoding).
#pragma once

#include <cmath>

namespace tr {

// Linear value in [0, 1] → non-linear sRGB value in [0, 1]; the input is clamped to [0, 1].
inline float srgb_encode(float linear) {
  float c = std::fmin(std::fmax(linear, 0.0f), 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Non-linear sRGB value in [0, 1] → linear value in [0, 1].
inline float srgb_decode(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace tr
