// A render in progress: every pixel's accumulated samples and the statistics so far. Backends
// add consecutive sample ranges to it (render.h, Renderer), so a render can stop, be written
// and go on. The CPU adds each pixel's samples one at a time in index order (Welford), so any
// split of [0, n) gives the same state bit for bit; the GPU merges batches whose boundaries are
// fixed multiples of its batch size, so any split on those boundaries does. Both end a pixel's
// passes (film_moments.h PassMoments) on the multiples of pass_size, which no batch straddles.
#pragma once

#include <cstdint>
#include <vector>

#include "render/error_estimate.h"
#include "render/film_moments.h"
#include "render/render.h"

namespace tr {

// The moments of `size()` accumulators (one a pixel, or aov_count a pixel), each part of
// FilmMoments in its own array, so that a film holds only the parts its render fills: the
// negative samples' groups once a sample of a filter with negative lobes arrives
// (keep_negative()), the passes' only with a correlated sampler. The positive samples' count is
// not stored: every sample of an accumulator is positive or negative, so it is the
// accumulator's sample count (the sample index the renderer is at, or FilmState::samples) less
// the negative count. For independent samples and filters without negative lobes that is 48
// bytes an accumulator instead of 200. An absent part reads as FilmMoments' zeros, which is what
// it would hold.
class FilmMomentArray {
 public:
  FilmMomentArray() = default;
  FilmMomentArray(std::size_t size, bool passes) : positive_(size), passes_(passes ? size : 0) {}

  std::size_t size() const { return positive_.size(); }
  bool empty() const { return positive_.empty(); }
  bool has_negative() const { return !negative_.empty(); }
  bool has_passes() const { return !passes_.empty(); }

  // Allocates the negative groups (all zero) unless they are there.
  void keep_negative() {
    if (negative_.empty()) negative_.resize(positive_.size());
  }

  // The positive samples of accumulator i, which holds `samples` samples in all.
  SampleGroup positive(std::size_t i, std::uint32_t samples) const {
    return positive_counted(i, double(samples) - (has_negative() ? negative_[i].n : 0.0));
  }
  // The same, given their count n (for a renderer whose threads must not read the negative
  // groups while another allocates them).
  SampleGroup positive_counted(std::size_t i, double n) const {
    SampleGroup g;
    g.n = n;
    for (int c = 0; c < 3; ++c) {
      g.mean[c] = positive_[i].mean[c];
      g.m2[c] = positive_[i].m2[c];
    }
    return g;
  }
  // Stores g's moments (its count is implied, above).
  void set_positive(std::size_t i, const SampleGroup& g) {
    for (int c = 0; c < 3; ++c) {
      positive_[i].mean[c] = g.mean[c];
      positive_[i].m2[c] = g.m2[c];
    }
  }
  // Only after keep_negative() (has_negative()).
  SampleGroup& negative(std::size_t i) { return negative_[i]; }
  // Only with passes (has_passes()).
  PassMoments& passes(std::size_t i) { return passes_[i]; }

  // Accumulator i whole, when it holds `samples` samples.
  FilmMoments at(std::size_t i, std::uint32_t samples) const {
    FilmMoments m;
    if (has_negative()) m.negative = negative_[i];
    m.positive = positive(i, samples);
    if (has_passes()) m.passes = passes_[i];
    return m;
  }

  // Stores m as accumulator i (m.positive.n + m.negative.n samples): its negative group
  // allocates the negative ones unless it is all zero; its pass moments are dropped without
  // passes, where nothing reads them (render/error_estimate.h).
  void set(std::size_t i, const FilmMoments& m) {
    set_positive(i, m.positive);
    if (!has_negative() && !is_zero(m.negative)) keep_negative();
    if (has_negative()) negative_[i] = m.negative;
    if (has_passes()) passes_[i] = m.passes;
  }

 private:
  // A SampleGroup without its count.
  struct Moments {
    double mean[3] = {0.0, 0.0, 0.0};
    double m2[3] = {0.0, 0.0, 0.0};
  };

  static bool is_zero(const SampleGroup& g) {
    if (g.n != 0.0) return false;
    for (int c = 0; c < 3; ++c)
      if (g.mean[c] != 0.0 || g.m2[c] != 0.0) return false;
    return true;
  }

  std::vector<Moments> positive_;
  std::vector<SampleGroup> negative_;  // empty: no negative sample yet
  std::vector<PassMoments> passes_;    // empty without passes
};

struct FilmState {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t samples = 0;  // samples per pixel accumulated: indices [0, samples)
  // Samples of one pass of a correlated sampler (its sample_count; a pass ends after sample
  // index i when (i + 1) % pass_size == 0), 0 for a sampler without passes (independent).
  std::uint32_t pass_size = 0;
  FilmMomentArray pixels;
  RenderStats stats;  // seconds: sampling time so far, plus the one acceleration build
  // Mitsuba `aov` (core/integrators/aov.h): each pixel's samples of aov_count output
  // variables, as three channels each, pixel-major: aovs[pixel * aov_count + i].
  std::uint32_t aov_count = 0;
  FilmMomentArray aovs;
};

inline FilmState empty_film(std::uint32_t width, std::uint32_t height, std::uint32_t aov_count = 0,
                            std::uint32_t pass_size = 0) {
  FilmState f;
  f.width = width;
  f.height = height;
  f.pass_size = pass_size;
  const std::size_t pixels = std::size_t(width) * height;
  f.pixels = FilmMomentArray(pixels, pass_size > 0);
  f.aov_count = aov_count;
  f.aovs = FilmMomentArray(pixels * aov_count, pass_size > 0);
  return f;
}

// Each pixel's value and variance output (render/error_estimate.h), RGB row-major.
inline void develop_film(const FilmState& film, std::vector<double>& mean,
                         std::vector<double>& variance) {
  mean.assign(3 * film.pixels.size(), 0.0);
  variance.assign(3 * film.pixels.size(), 0.0);
  for (std::size_t p = 0; p < film.pixels.size(); ++p)
    develop_estimate(film.pixels.at(p, film.samples), film.pass_size, &mean[3 * p],
                     &variance[3 * p]);
}

// The same for the AOVs: 3 * aov_count values per pixel, in FilmState::aovs order.
inline void develop_aovs(const FilmState& film, std::vector<double>& mean,
                         std::vector<double>& variance) {
  mean.assign(3 * film.aovs.size(), 0.0);
  variance.assign(3 * film.aovs.size(), 0.0);
  for (std::size_t a = 0; a < film.aovs.size(); ++a)
    develop_estimate(film.aovs.at(a, film.samples), film.pass_size, &mean[3 * a], &variance[3 * a]);
}

}  // namespace tr
