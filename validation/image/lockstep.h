// Lockstep agreement: for two renders that should be identical up to floating-point rounding
// (the CPU and GPU backends with the same sampler seed), the fraction of pixels whose channels
// all satisfy |a - b| <= rel max(|a|, |b|) + abs, the worst pixels, and a check for small
// systematic differences that stay under the per-pixel tolerance.
//
// Systematic-difference check: over non-overlapping block x block cells (partial cells at the
// right and bottom borders are left out) and per channel, the mean signed difference
// d̄ = mean(a - b) is compared with its standard error s / block, s the sample standard
// deviation of the block^2 differences, by a two-sided one-sample t-test with block^2 - 1
// degrees of freedom (Student 1908). A cell is flagged when p <= 1 - (1 - family_alpha)^(1 /
// (cells * 3)) (Šidák) and |d̄| > abs; a cell whose differences are all equal and non-zero
// has s = 0 and p = 0.
//
// The comparison passes when at least required_fraction of the pixels are within tolerance and
// no cell is flagged.
#pragma once

#include <vector>

#include "validation/image/rgb_image.h"

namespace tr {

struct LockstepOptions {
  double rel = 1e-4;
  double abs = 1e-6;
  double required_fraction = 0.999;
  int worst_count = 10;
  int block = 4;
  double family_alpha = 0.01;
};

struct LockstepPixel {
  int x = 0, y = 0;
  double a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
  double excess = 0.0;  // max over channels of |a - b| / (rel max(|a|, |b|) + abs); > 1 fails
};

struct LockstepBlock {
  int x = 0, y = 0, channel = 0;  // cell coordinates
  double mean_difference = 0.0, t = 0.0, p = 1.0;
};

struct LockstepResult {
  size_t pixels = 0, pixels_outside = 0;
  double fraction_within = 0.0;
  double max_abs_difference = 0.0;
  std::vector<LockstepPixel> worst;  // largest excess first, at most worst_count
  std::vector<float> excess_map;     // per pixel
  int cells_x = 0, cells_y = 0;
  double block_alpha = 0.0;
  size_t systematic_cells = 0;              // cells with a flagged channel
  std::vector<LockstepBlock> worst_blocks;  // smallest p first, at most worst_count
  bool passed = false;
};

LockstepResult lockstep_compare(const RgbImage& a, const RgbImage& b,
                                const LockstepOptions& options = {});

}  // namespace tr
