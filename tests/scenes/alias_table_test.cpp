// Vose alias tables: the distribution each table implies equals the requested pmf.
#include "scenes/alias_table.h"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

namespace tr {
namespace {

// Probability of bin i under alias sampling: (q_i + sum over j aliasing to i of (1 - q_j)) / n.
std::vector<double> implied_pmf(const std::vector<AliasEntry>& table) {
  std::vector<double> p(table.size(), 0.0);
  for (size_t j = 0; j < table.size(); ++j) {
    p[j] += table[j].q / double(table.size());
    p[table[j].alias] += (1.0 - table[j].q) / double(table.size());
  }
  return p;
}

TEST(AliasTable, ImpliedDistributionIsThePmf) {
  std::vector<std::vector<double>> cases = {
      {1.0}, {1, 1, 1, 1}, {1, 2, 3, 4}, {0, 5, 0, 1e-6, 3}, {1e6, 1, 1, 1, 1, 1, 1}};
  for (const auto& w : cases) {
    std::vector<AliasEntry> t = build_alias_table(w);
    double sum = std::accumulate(w.begin(), w.end(), 0.0);
    std::vector<double> p = implied_pmf(t);
    double pmf_sum = 0.0;
    for (size_t i = 0; i < w.size(); ++i) {
      EXPECT_NEAR(t[i].pmf, w[i] / sum, 1e-7);
      EXPECT_NEAR(p[i], w[i] / sum, 1e-6);
      EXPECT_GE(t[i].q, 0.0f);
      EXPECT_LE(t[i].q, 1.0f);
      EXPECT_LT(t[i].alias, w.size());
      pmf_sum += t[i].pmf;
    }
    EXPECT_NEAR(pmf_sum, 1.0, 1e-6);
  }
}

TEST(AliasTable, RejectsInvalidWeights) {
  EXPECT_THROW(build_alias_table({}), std::invalid_argument);
  EXPECT_THROW(build_alias_table({0, 0}), std::invalid_argument);
  EXPECT_THROW(build_alias_table({1, -1}), std::invalid_argument);
  EXPECT_THROW(build_alias_table({1, std::numeric_limits<double>::infinity()}),
               std::invalid_argument);
}

}  // namespace
}  // namespace tr
