// Per-pixel accumulation of the GPU's batches in double: each batch's positive and negative
// samples (PixelBatch) are merged into render/film_moments.h's groups with the pairwise update
// of Chan, Golub & LeVeque, "Updating Formulae and a Pairwise Algorithm for Computing Sample
// Variances" (1979), eq. 2.1, and developed as the CPU backend develops its pixels, so that
// RenderResult.mean/variance have the same semantics on both backends.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/film_moments.h"
#include "render/film_state.h"
#include "shaders/batch.h"

namespace tr {

// Merges one batch of n_b samples per pixel, the sample indices [first, first + n_b), into
// `pixels` (one accumulator per pixel). With pass_size > 0 (FilmState::pass_size) the batch must
// lie inside one pass: it joins the pass in progress, and ends it when first + n_b is a multiple
// of pass_size.
void merge_batches(const PixelBatch* batch, std::uint32_t first, std::uint32_t n_b,
                   std::uint32_t pass_size, FilmMomentArray& pixels);

class MomentAccumulator {
 public:
  explicit MomentAccumulator(std::size_t pixels);

  // Merges one batch of n_b samples per pixel (without passes).
  void merge(const PixelBatch* batch, std::uint32_t n_b);

  std::uint64_t count() const { return count_; }
  // Each pixel's value and per-sample variance (render/film_moments.h develop), per channel.
  void develop(std::vector<double>& mean, std::vector<double>& variance) const;

 private:
  std::uint64_t count_ = 0;
  FilmMomentArray pixels_;
};

}  // namespace tr
