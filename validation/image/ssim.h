// Structural similarity (Wang, Bovik, Sheikh & Simoncelli, "Image Quality Assessment: From
// Error Visibility to Structural Similarity", IEEE TIP 13(4), 2004).
//
// Input to SSIM, stated exactly: each linear RGB channel is clamped to [0, 1] and sRGB-encoded
// (IEC 61966-2-1), then reduced to luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' (BT.709
// weights on the encoded values), dynamic range L = 1. Local statistics use the paper's 11x11
// circular-symmetric Gaussian window, sigma 1.5, normalised to unit sum (§III-C of the paper),
// evaluated only where the window lies inside the image, with K1 = 0.01, K2 = 0.03, C1 = (K1 L)^2,
// C2 = (K2 L)^2 (eq. 13). The score is the mean of the SSIM map (MSSIM, eq. 17).
#pragma once

#include <vector>

#include "validation/image/rgb_image.h"

namespace tr {

constexpr int kSsimWindow = 11;

struct SsimResult {
  double mean = 0.0;
  int map_width = 0, map_height = 0;  // (width - 10) x (height - 10)
  std::vector<float> map;
};

// Throws std::invalid_argument if an image is smaller than 11x11 pixels.
SsimResult ssim(const RgbImage& test, const RgbImage& reference);

}  // namespace tr
