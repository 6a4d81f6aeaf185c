#include "gpu_backend/variance_merge.h"

namespace tr {

MomentAccumulator::MomentAccumulator(std::size_t pixels) : pixels_(pixels) {}

void merge_batches(const PixelBatch* batch, std::uint32_t first, std::uint32_t n_b,
                   std::uint32_t pass_size, std::vector<FilmMoments>& pixels) {
  const bool ends_pass = pass_size > 0 && (first + n_b) % pass_size == 0;
  for (std::size_t p = 0; p < pixels.size(); ++p) {
    const double negative = static_cast<double>(batch[p].negative);
    const double positive = static_cast<double>(n_b) - negative;
    merge_batch(pixels[p].positive, positive, batch[p].mean, batch[p].m2);
    merge_batch(pixels[p].negative, negative, batch[p].mean_negative, batch[p].m2_negative);
    if (pass_size == 0) continue;
    PassMoments& pass = pixels[p].passes;
    if (positive > 0.0) add_to_pass(pass, 1.0, positive, batch[p].mean);
    if (negative > 0.0) add_to_pass(pass, -1.0, negative, batch[p].mean_negative);
    if (ends_pass) end_pass(pass);
  }
}

void MomentAccumulator::merge(const PixelBatch* batch, std::uint32_t n_b) {
  merge_batches(batch, static_cast<std::uint32_t>(count_), n_b, 0, pixels_);
  count_ += n_b;
}

void MomentAccumulator::develop(std::vector<double>& mean, std::vector<double>& variance) const {
  mean.assign(3 * pixels_.size(), 0.0);
  variance.assign(3 * pixels_.size(), 0.0);
  for (std::size_t p = 0; p < pixels_.size(); ++p)
    tr::develop(pixels_[p], &mean[3 * p], &variance[3 * p]);
}

}  // namespace tr
