// LDR-FLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström & Fairchild, "FLIP: A
// Difference Evaluator for Alternating Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2),
// HPG 2020). Comments name the paper's steps; the constants are the paper's.
//
// Inputs are linear RGB images; they are clamped to [0, 1], which is what FLIP sees after
// decoding an 8-bit-range sRGB image (LDR-FLIP takes sRGB images). Both pipelines of the paper are
// implemented in full: the colour pipeline (CSF filtering in YyCxCz, clamp to the RGB
// cube, L*a*b*, Hunt adjustment, HyAB distance, error redistribution) and the feature
// pipeline (edge and point detection on the achromatic channel), combined per pixel as
// ΔE = ΔE_c^(1 - ΔE_f). Image borders are handled by replicating the
// edge pixels, as in the authors' reference implementation.
#pragma once

#include <vector>

#include "validation/image/rgb_image.h"

namespace tr {

// Pixels per degree of visual angle for the paper's default observer: a 0.7 m wide monitor
// with 3840 pixels per row viewed from 0.7 m, ppd = d (r / w) π / 180 ≈ 67.02.
double flip_default_pixels_per_degree();

struct FlipResult {
  std::vector<float> map;  // per-pixel FLIP error in [0, 1]
  // Pooled values (Andersson et al., "Visualizing and Communicating Errors in Rendered
  // Images", Ray Tracing Gems II, 2021, ch. 19): the mean, and weighted percentiles, i.e. the
  // error e_p such that errors <= e_p make up p percent of the sum of all errors.
  double mean = 0.0;
  double weighted_median = 0.0;
  double weighted_quartile1 = 0.0, weighted_quartile3 = 0.0;
  double min = 0.0, max = 0.0;
};

// `reference` is the paper's reference image, `test` its test image.
FlipResult ldr_flip(const RgbImage& test, const RgbImage& reference,
                    double pixels_per_degree = flip_default_pixels_per_degree());

}  // namespace tr
