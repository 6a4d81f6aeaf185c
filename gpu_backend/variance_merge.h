// Per-pixel sample mean and sum of squared deviations (M2) in double, merged batch by batch
// with the pairwise update of Chan, Golub & LeVeque, "Updating Formulae and a Pairwise
// Algorithm for Computing Sample Variances" (1979), eq. 2.1: for sets A and B,
//   n = n_A + n_B,  delta = mean_B - mean_A,
//   mean = mean_A + delta n_B / n,  M2 = M2_A + M2_B + delta^2 n_A n_B / n.
// This gives RenderResult.mean/variance the CPU backend's Welford semantics.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "shaders/batch.h"

namespace tr {

class MomentAccumulator {
 public:
  explicit MomentAccumulator(std::size_t pixels);

  // Merges one batch of n_b samples per pixel.
  void merge(const PixelBatch* batch, std::uint32_t n_b);

  std::uint64_t count() const { return count_; }
  const std::vector<double>& mean() const { return mean_; }
  // Unbiased per-sample variance M2 / (n - 1), per pixel and channel; 0 below two samples.
  std::vector<double> variance() const;

 private:
  std::size_t pixels_;
  std::uint64_t count_ = 0;
  std::vector<double> mean_;
  std::vector<double> m2_;
};

}  // namespace tr
