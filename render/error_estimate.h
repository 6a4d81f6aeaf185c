// What a render's variance output estimates: the one place that decides it. The output is a
// per-sample variance v, so that v / n estimates the variance of a pixel's value after n
// samples. With independent samples that is the per-sample variance of develop
// (render/film_moments.h). A correlated sampler's samples (core/rng.h: passes of S stratified or
// low-discrepancy points) are not independent, and the per-sample variance over n says nothing
// about the error of their mean; its passes are, though, independent randomizations (randomized
// QMC, Owen, Monte Carlo theory, methods and examples, §17.1): with K >= 2 completed passes of
// value Y_k, s^2 = sum (Y_k - Ybar)^2 / (K - 1) estimates the variance of one pass's value
// without bias and s^2 / K that of their mean, so v = S s^2 (v / n = s^2 / K for n = K S).
// Below 2 passes a correlated sampler's variance stays the per-sample one, which is no estimate
// of its error (render_command warns).
#pragma once

#include <cstdint>
#include <string>

#include "render/film_moments.h"

namespace tr {

// Completed passes after `samples` samples per pixel; 0 without passes (pass_size 0).
inline std::uint32_t completed_passes(std::uint32_t pass_size, std::uint32_t samples) {
  return pass_size > 0 ? samples / pass_size : 0;
}

// Whether the variance output rests on the passes (else it is the per-sample variance).
inline bool variance_from_passes(std::uint32_t pass_size, std::uint32_t samples) {
  return completed_passes(pass_size, samples) >= 2;
}

// The pixel's value (develop) and its variance output v, per channel.
inline void develop_estimate(const FilmMoments& m, std::uint32_t pass_size, double mean[3],
                             double variance[3]) {
  develop(m, mean, variance);
  const SampleGroup& passes = m.passes.values;
  if (pass_size == 0 || passes.n < 2.0) return;
  for (int c = 0; c < 3; ++c) variance[c] = double(pass_size) * passes.m2[c] / (passes.n - 1.0);
}

// The EXR attribute twinray:variance_estimate: "per-sample" or "randomizations: K passes of S
// samples".
inline std::string variance_estimate_name(std::uint32_t pass_size, std::uint32_t samples) {
  if (!variance_from_passes(pass_size, samples)) return "per-sample";
  return "randomizations: " + std::to_string(completed_passes(pass_size, samples)) + " passes of " +
         std::to_string(pass_size) + " samples";
}

}  // namespace tr
