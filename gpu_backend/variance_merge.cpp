#include "gpu_backend/variance_merge.h"

namespace tr {

MomentAccumulator::MomentAccumulator(std::size_t pixels)
    : pixels_(pixels), mean_(3 * pixels, 0.0), m2_(3 * pixels, 0.0) {}

void MomentAccumulator::merge(const PixelBatch* batch, std::uint32_t n_b) {
  if (n_b == 0) return;
  const double na = static_cast<double>(count_);
  const double nb = static_cast<double>(n_b);
  const double n = na + nb;
  for (std::size_t p = 0; p < pixels_; ++p)
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = 3 * p + c;
      const double delta = static_cast<double>(batch[p].mean[c]) - mean_[i];
      mean_[i] += delta * nb / n;
      m2_[i] += static_cast<double>(batch[p].m2[c]) + delta * delta * na * nb / n;
    }
  count_ += n_b;
}

std::vector<double> MomentAccumulator::variance() const {
  std::vector<double> v(m2_.size(), 0.0);
  if (count_ < 2) return v;
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = m2_[i] / static_cast<double>(count_ - 1);
  return v;
}

}  // namespace tr
