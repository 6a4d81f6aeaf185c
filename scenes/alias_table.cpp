#include "scenes/alias_table.h"

#include <cmath>
#include <stdexcept>

namespace tr {

std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights) {
  const size_t n = weights.size();
  if (n == 0) throw std::invalid_argument("alias table: no weights");
  double sum = 0.0;
  for (double w : weights) {
    if (!(w >= 0.0) || !std::isfinite(w))
      throw std::invalid_argument("alias table: weights must be finite and non-negative");
    sum += w;
  }
  if (!(sum > 0.0)) throw std::invalid_argument("alias table: all weights are zero");

  std::vector<AliasEntry> table(n);
  std::vector<double> scaled(n);  // n p_i, Vose's "prob" before pairing
  std::vector<size_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    table[i].pmf = float(weights[i] / sum);
    table[i].alias = uint(i);
    table[i].pad = 0u;
    scaled[i] = weights[i] / sum * double(n);
    (scaled[i] < 1.0 ? small : large).push_back(i);
  }
  while (!small.empty() && !large.empty()) {
    size_t l = small.back(), g = large.back();
    small.pop_back();
    large.pop_back();
    table[l].q = float(scaled[l]);
    table[l].alias = uint(g);
    scaled[g] = (scaled[g] + scaled[l]) - 1.0;
    (scaled[g] < 1.0 ? small : large).push_back(g);
  }
  // What is left holds probability 1 up to rounding (Vose, section III).
  for (size_t g : large) table[g].q = 1.0f;
  for (size_t l : small) table[l].q = 1.0f;
  return table;
}

}  // namespace tr
