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

struct FilmState {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t samples = 0;  // samples per pixel accumulated: indices [0, samples)
  // Samples of one pass of a correlated sampler (its sample_count; a pass ends after sample
  // index i when (i + 1) % pass_size == 0), 0 for a sampler without passes (independent).
  std::uint32_t pass_size = 0;
  std::vector<FilmMoments> pixels;
  RenderStats stats;  // seconds: sampling time so far, plus the one acceleration build
  // Mitsuba `aov` (core/integrators/aov.h): each pixel's samples of aov_count output
  // variables, as three channels each, pixel-major: aovs[pixel * aov_count + i].
  std::uint32_t aov_count = 0;
  std::vector<FilmMoments> aovs;
};

inline FilmState empty_film(std::uint32_t width, std::uint32_t height, std::uint32_t aov_count = 0,
                            std::uint32_t pass_size = 0) {
  FilmState f;
  f.width = width;
  f.height = height;
  f.pass_size = pass_size;
  f.pixels.resize(std::size_t(width) * height);
  f.aov_count = aov_count;
  f.aovs.resize(f.pixels.size() * aov_count);
  return f;
}

// Each pixel's value and variance output (render/error_estimate.h), RGB row-major.
inline void develop_film(const FilmState& film, std::vector<double>& mean,
                         std::vector<double>& variance) {
  mean.assign(3 * film.pixels.size(), 0.0);
  variance.assign(3 * film.pixels.size(), 0.0);
  for (std::size_t p = 0; p < film.pixels.size(); ++p)
    develop_estimate(film.pixels[p], film.pass_size, &mean[3 * p], &variance[3 * p]);
}

// The same for the AOVs: 3 * aov_count values per pixel, in FilmState::aovs order.
inline void develop_aovs(const FilmState& film, std::vector<double>& mean,
                         std::vector<double>& variance) {
  mean.assign(3 * film.aovs.size(), 0.0);
  variance.assign(3 * film.aovs.size(), 0.0);
  for (std::size_t a = 0; a < film.aovs.size(); ++a)
    develop_estimate(film.aovs[a], film.pass_size, &mean[3 * a], &variance[3 * a]);
}

}  // namespace tr
