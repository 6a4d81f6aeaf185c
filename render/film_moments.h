// A pixel's samples as both backends accumulate them (in double on the host): the positive and
// the negative samples of the film estimator (core/film.h) apart, each as a count, mean and
// sum of squared deviations M2, updated one sample at a time (Welford 1962) or one batch at a
// time (Chan, Golub & LeVeque 1979, eq. 2.1), and developed into the pixel's value and
// per-sample variance. Without negative samples (filters without negative lobes) the value is
// the positive samples' mean and the variance M2 / (n - 1), exactly.
// With a correlated sampler (core/rng.h: passes of sample_count stratified or low-discrepancy
// points, each pass an independent randomization) the samples of a pass are not independent;
// PassMoments keeps, beside them, the Welford moments of the completed passes' pixel values
// and the sums of the pass in progress (render/error_estimate.h turns them into the error).
#pragma once

#include <cstdint>

namespace tr {

struct SampleGroup {
  double n = 0.0;
  double mean[3] = {0.0, 0.0, 0.0};
  double m2[3] = {0.0, 0.0, 0.0};
};

// One pixel's passes: the values of the completed ones (n: how many) and, for the pass in
// progress, sum(s) and sum(s L) over its samples (s = +-1 as in develop).
struct PassMoments {
  SampleGroup values;
  double signs = 0.0;
  double sum[3] = {0.0, 0.0, 0.0};
};

struct FilmMoments {
  SampleGroup positive, negative;
  PassMoments passes;  // untouched (all zero) for samplers without passes (independent)
};

// Welford's update with the sample L.
template <typename Vec3>
void add_sample(SampleGroup& g, const Vec3& L) {
  g.n += 1.0;
  for (int c = 0; c < 3; ++c) {
    double delta = double(L[c]) - g.mean[c];
    g.mean[c] += delta / g.n;
    g.m2[c] += delta * (double(L[c]) - g.mean[c]);
  }
}

// Chan et al.'s pairwise update with a batch of n_b samples of mean `mean_b` and M2 `m2_b`.
template <typename Vec3>
void merge_batch(SampleGroup& g, double n_b, const Vec3& mean_b, const Vec3& m2_b) {
  if (n_b == 0.0) return;
  const double n = g.n + n_b;
  for (int c = 0; c < 3; ++c) {
    const double delta = double(mean_b[c]) - g.mean[c];
    g.mean[c] += delta * n_b / n;
    g.m2[c] += double(m2_b[c]) + delta * delta * g.n * n_b / n;
  }
  g.n = n;
}

// Adds n_b samples of sign s and mean `mean_b` to the pass in progress (n_b = 1: one sample).
template <typename Vec3>
void add_to_pass(PassMoments& p, double s, double n_b, const Vec3& mean_b) {
  p.signs += s * n_b;
  for (int c = 0; c < 3; ++c) p.sum[c] += s * n_b * double(mean_b[c]);
}

// Ends the pass in progress: its value sum(s L) / sum(s), divided as develop divides (by 1
// where the sum of signs is 0), joins the completed values (Welford), and the sums restart.
inline void end_pass(PassMoments& p) {
  const double divisor = p.signs != 0.0 ? p.signs : 1.0;
  double value[3];
  for (int c = 0; c < 3; ++c) value[c] = p.sum[c] / divisor;
  add_sample(p.values, value);
  p.signs = 0.0;
  for (double& s : p.sum) s = 0.0;
}

// The pixel's value sum(s L) / sum(s) (s = +-1; like hdrfilm's division by the weight channel,
// by 1 where the sum of signs is 0) and the per-sample variance v of that estimate, so that
// the value's variance is about v / n: by the delta method, v = [sum (L - mean)^2 / (n - 1)] /
// (sum(s) / n)^2 (Owen, Monte Carlo theory, methods and examples, §9.2, ratio estimators).
inline void develop(const FilmMoments& m, double mean[3], double variance[3]) {
  const SampleGroup& p = m.positive;
  const SampleGroup& q = m.negative;
  const double n = p.n + q.n;
  if (q.n == 0.0) {
    for (int c = 0; c < 3; ++c) {
      mean[c] = p.mean[c];
      variance[c] = n > 1.0 ? p.m2[c] / (n - 1.0) : 0.0;
    }
    return;
  }
  const double signs = p.n - q.n;
  const double divisor = signs != 0.0 ? signs : 1.0;
  const double scale = signs != 0.0 ? (n / signs) * (n / signs) : 1.0;
  for (int c = 0; c < 3; ++c) {
    mean[c] = (p.n * p.mean[c] - q.n * q.mean[c]) / divisor;
    const double dp = p.mean[c] - mean[c], dq = q.mean[c] - mean[c];
    const double squares = p.m2[c] + p.n * dp * dp + q.m2[c] + q.n * dq * dq;
    variance[c] = n > 1.0 ? scale * squares / (n - 1.0) : 0.0;
  }
}

}  // namespace tr
