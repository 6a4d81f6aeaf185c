// The error a render in progress has reached, estimated from its own variance: the root of the
// expected relMSE of Rousselle et al. 2011 (validation/image/metrics.h: mean over pixels and
// channels of (a - b)^2 / (b^2 + 0.01)). For an unbiased render the expected squared error of
// a value is its variance over the sample count, var / n, so with the render's own mean m for
// the reference the estimate is sqrt(mean(var / (n (m^2 + 0.01)))). The 0.01 keeps dark pixels,
// whose relative error is unbounded, from deciding alone: it is the metric `twinray converge`
// reports, so `render --target-error E` stops where converge would measure about E^2.
// Below kMinErrorSamples samples per pixel the variances are too noisy to stop on (at 1 they
// are all 0), and the estimate is infinite. With a correlated sampler the variances are those of
// its passes (render/error_estimate.h), with K - 1 degrees of freedom: below kMinErrorPasses
// completed passes the estimate is infinite (before 2 it would be no error estimate at all).
#pragma once

#include <cmath>

#include "render/film_state.h"

namespace tr {

constexpr std::uint32_t kMinErrorSamples = 16;
constexpr std::uint32_t kMinErrorPasses = 16;

inline double estimated_relative_error(const FilmState& film) {
  if (film.samples < kMinErrorSamples || film.pixels.empty()) return INFINITY;
  if (film.pass_size > 0 && completed_passes(film.pass_size, film.samples) < kMinErrorPasses)
    return INFINITY;
  // Pixel by pixel (develop_film's values, summed in its order) rather than through a developed
  // copy of the film, which would be 48 bytes a pixel more while the render runs.
  double sum = 0.0;
  for (std::size_t p = 0; p < film.pixels.size(); ++p) {
    double mean[3], variance[3];
    develop_estimate(film.pixels.at(p, film.samples), film.pass_size, mean, variance);
    for (int c = 0; c < 3; ++c)
      sum += variance[c] / (double(film.samples) * (mean[c] * mean[c] + 1e-2));
  }
  return std::sqrt(sum / double(3 * film.pixels.size()));
}

}  // namespace tr
