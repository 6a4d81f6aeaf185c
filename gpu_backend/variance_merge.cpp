#include "gpu_backend/variance_merge.h"

namespace tr {

MomentAccumulator::MomentAccumulator(std::size_t pixels) : pixels_(pixels) {}

void merge_batches(const PixelBatch* batch, std::uint32_t n_b, std::vector<FilmMoments>& pixels) {
  for (std::size_t p = 0; p < pixels.size(); ++p) {
    const double negative = static_cast<double>(batch[p].negative);
    merge_batch(pixels[p].positive, static_cast<double>(n_b) - negative, batch[p].mean,
                batch[p].m2);
    merge_batch(pixels[p].negative, negative, batch[p].mean_negative, batch[p].m2_negative);
  }
}

void MomentAccumulator::merge(const PixelBatch* batch, std::uint32_t n_b) {
  merge_batches(batch, n_b, pixels_);
  count_ += n_b;
}

void MomentAccumulator::develop(std::vector<double>& mean, std::vector<double>& variance) const {
  mean.assign(3 * pixels_.size(), 0.0);
  variance.assign(3 * pixels_.size(), 0.0);
  for (std::size_t p = 0; p < pixels_.size(); ++p)
    tr::develop(pixels_[p], &mean[3 * p], &variance[3 * p]);
}

}  // namespace tr
