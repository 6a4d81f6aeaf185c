#include "gpu_backend/variance_merge.h"

#include <stdexcept>
#include <string>

namespace tr {

MomentAccumulator::MomentAccumulator(std::size_t pixels) : pixels_(pixels, false) {}

void merge_batches(const PixelBatch* batch, std::uint32_t first, std::uint32_t n_b,
                   std::uint32_t pass_size, FilmMomentArray& pixels) {
  if (pass_size > 0 && !pixels.has_passes())
    throw std::logic_error("merge_batches: pass size " + std::to_string(pass_size) +
                           " without pass moments (render/film_state.h FilmMomentArray)");
  const bool ends_pass = pass_size > 0 && (first + n_b) % pass_size == 0;
  // The negative groups exist once a negative sample has arrived; merging none changes nothing.
  for (std::size_t p = 0; p < pixels.size() && !pixels.has_negative(); ++p)
    if (batch[p].negative > 0) pixels.keep_negative();
  for (std::size_t p = 0; p < pixels.size(); ++p) {
    const double negative = static_cast<double>(batch[p].negative);
    const double positive = static_cast<double>(n_b) - negative;
    SampleGroup g = pixels.positive(p, first);
    merge_batch(g, positive, batch[p].mean, batch[p].m2);
    pixels.set_positive(p, g);
    if (pixels.has_negative())
      merge_batch(pixels.negative(p), negative, batch[p].mean_negative, batch[p].m2_negative);
    if (pass_size == 0) continue;
    PassMoments& pass = pixels.passes(p);
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
    tr::develop(pixels_.at(p, static_cast<std::uint32_t>(count_)), &mean[3 * p], &variance[3 * p]);
}

}  // namespace tr
