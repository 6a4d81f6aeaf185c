#include "validation/image/lockstep.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "validation/image/statistics.h"

namespace tr {

namespace {

// P(X >= k) for X ~ Binomial(n, f).
double binomial_upper_tail(int n, int k, double f) {
  if (k <= 0) return 1.0;
  if (f <= 0.0) return 0.0;
  double tail = 0.0;
  for (int j = k; j <= n; ++j)
    tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(j + 1.0) - std::lgamma(n - j + 1.0) +
                     j * std::log(f) + (n - j) * std::log1p(-f));
  return std::min(tail, 1.0);
}

}  // namespace

LockstepResult lockstep_compare(const RgbImage& a, const RgbImage& b,
                                const LockstepOptions& options, const RgbImage* rounding_control) {
  check_same_size(a, "first image", b, "second image");
  if (rounding_control) check_same_size(*rounding_control, "rounding control", b, "second image");
  if (options.block < 2) throw std::invalid_argument("lockstep block size must be at least 2");
  LockstepResult r;
  r.pixels = a.pixel_count();
  r.rounding_controlled = rounding_control != nullptr;
  r.excess_map.resize(r.pixels);
  std::vector<char> sensitive(r.pixels, 0);
  size_t outside_sensitive = 0;
  std::vector<LockstepPixel> all(r.pixels);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      LockstepPixel& p = all[size_t(y) * a.width + x];
      p.x = x;
      p.y = y;
      for (int c = 0; c < 3; ++c) {
        p.a[c] = a.at(x, y, c);
        p.b[c] = b.at(x, y, c);
        double d = std::fabs(p.a[c] - p.b[c]);
        double tolerance =
            options.rel * std::max(std::fabs(p.a[c]), std::fabs(p.b[c])) + options.abs;
        p.excess = std::max(p.excess, d / tolerance);
        r.max_abs_difference = std::max(r.max_abs_difference, d);
        if (rounding_control) {
          double vc = rounding_control->at(x, y, c);
          double control_tolerance =
              options.rel * std::max(std::fabs(vc), std::fabs(p.b[c])) + options.abs;
          if (std::fabs(vc - p.b[c]) > options.rounding_share * control_tolerance)
            sensitive[size_t(y) * a.width + x] = 1;
        }
      }
      r.rounding_sensitive += sensitive[size_t(y) * a.width + x];
      r.excess_map[size_t(y) * a.width + x] = float(p.excess);
      if (p.excess > 1.0) ++r.pixels_outside;
      if (p.excess > 1.0 && sensitive[size_t(y) * a.width + x]) ++outside_sensitive;
    }
  r.fraction_within = double(r.pixels - r.pixels_outside) / double(r.pixels);
  const bool well_conditioned_only = options.fraction_over_well_conditioned && rounding_control;
  if (well_conditioned_only && r.pixels > r.rounding_sensitive)
    r.fraction_within =
        double(r.pixels - r.rounding_sensitive - (r.pixels_outside - outside_sensitive)) /
        double(r.pixels - r.rounding_sensitive);
  size_t worst_n = std::min(all.size(), size_t(std::max(options.worst_count, 0)));
  std::partial_sort(
      all.begin(), all.begin() + worst_n, all.end(),
      [](const LockstepPixel& p, const LockstepPixel& q) { return p.excess > q.excess; });
  r.worst.assign(all.begin(), all.begin() + worst_n);

  const int B = options.block, n = B * B;
  const int windows_x = std::max(a.width - B + 1, 0), windows_y = std::max(a.height - B + 1, 0);
  r.windows = size_t(windows_x) * size_t(windows_y);
  r.block_alpha = sidak_alpha(options.family_alpha, 3.0 * double(r.windows));
  std::vector<LockstepBlock> flagged;
  for (int wy = 0; wy < windows_y; ++wy)
    for (int wx = 0; wx < windows_x; ++wx) {
      bool cell_flagged = false;
      for (int c = 0; c < 3; ++c) {
        // The difference in units of the pixel's tolerance, so that a relative bias is the
        // same number at every brightness.
        auto difference = [&](int i) {
          int x = wx + i % B, y = wy + i / B;
          double va = a.at(x, y, c), vb = b.at(x, y, c);
          return (va - vb) / (options.rel * std::max(std::fabs(va), std::fabs(vb)) + options.abs);
        };
        LockstepBlock blk;
        blk.x = wx;
        blk.y = wy;
        blk.channel = c;
        for (int i = 0; i < n; ++i) blk.mean_difference += difference(i) / n;
        double s2 = 0.0;  // two-pass sample variance
        for (int i = 0; i < n; ++i)
          s2 += std::pow(difference(i) - blk.mean_difference, 2) / (n - 1);
        double standard_error = std::sqrt(s2 / n);
        if (standard_error > 0.0) {
          blk.t = blk.mean_difference / standard_error;
          blk.p = student_two_sided_p(blk.t, n - 1);
        } else if (blk.mean_difference != 0.0) {
          blk.t = std::copysign(INFINITY, blk.mean_difference);
          blk.p = 0.0;
        }
        if (blk.p <= r.block_alpha && std::fabs(blk.mean_difference) > options.systematic_floor) {
          cell_flagged = true;
          flagged.push_back(blk);
        }
      }
      if (cell_flagged) ++r.systematic_cells;
    }
  auto outside_and_insensitive = [&](size_t i) { return r.excess_map[i] > 1.0f && !sensitive[i]; };
  size_t cluster_candidates = 0;
  for (size_t i = 0; i < r.pixels; ++i) cluster_candidates += outside_and_insensitive(i);
  const double f = double(cluster_candidates) / double(r.pixels);
  for (int wy = 0; wy < windows_y; ++wy)
    for (int wx = 0; wx < windows_x; ++wx) {
      int k = 0;
      for (int i = 0; i < n; ++i)
        if (outside_and_insensitive(size_t(wy + i / B) * a.width + wx + i % B)) ++k;
      if (k > r.most_outside) {
        r.most_outside = k;
        r.most_outside_x = wx;
        r.most_outside_y = wy;
      }
      if (k > 0 && binomial_upper_tail(n, k, f) <= r.block_alpha) ++r.clustered_windows;
    }
  std::sort(flagged.begin(), flagged.end(),
            [](const LockstepBlock& p, const LockstepBlock& q) { return p.p < q.p; });
  if (flagged.size() > worst_n) flagged.resize(worst_n);
  r.worst_blocks = flagged;
  r.passed = r.fraction_within >= options.required_fraction && r.systematic_cells == 0 &&
             r.clustered_windows == 0;
  if (options.fraction_over_well_conditioned)
    r.passed = r.passed && rounding_control &&
               double(r.rounding_sensitive) <= options.max_rounding_sensitive * double(r.pixels);
  return r;
}

}  // namespace tr
