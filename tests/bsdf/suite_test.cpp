// The validation suite over core/: one test per family, each printing its report table.
#include <gtest/gtest.h>

#include <iostream>

#include "cases.h"
#include "suite_size.h"

namespace tr::bsdf_suite {
namespace {

std::string banner() {
  std::ostringstream s;
  s << (full_size() ? "full" : "fast") << " size; " << statistical_test_count()
    << " statistical tests at overall significance " << kSignificance
    << ", Sidak level per test alpha = " << alpha_per_test();
  return s.str();
}

class StatisticalFamily : public testing::TestWithParam<std::string> {};

TEST_P(StatisticalFamily, PassesAtSidakLevel) {
  twinray::validation::Report report = run_statistical_family(GetParam());
  std::cout << banner() << "\n";
  report.print(std::cout);
  ASSERT_FALSE(report.checks.empty());
  EXPECT_TRUE(report.passed()) << "see the FAIL rows above";
}

INSTANTIATE_TEST_SUITE_P(Chi2, StatisticalFamily, testing::ValuesIn(statistical_families()),
                         [](const testing::TestParamInfo<std::string>& i) { return i.param; });

class ExtremesFamily : public testing::TestWithParam<std::string> {};

TEST_P(ExtremesFamily, NoNanInfOrNegative) {
  twinray::validation::Report report = run_extremes_family(GetParam());
  std::size_t failed = 0;
  for (const auto& c : report.checks) failed += c.passed ? 0 : 1;
  std::cout << report.checks.size() << " parameter settings, " << failed << " failing\n";
  twinray::validation::Report failures;
  for (const auto& c : report.checks) {
    if (!c.passed) failures.checks.push_back(c);
  }
  if (failed > 0) failures.print(std::cout);
  ASSERT_FALSE(report.checks.empty());
  EXPECT_EQ(failed, 0u);
}

INSTANTIATE_TEST_SUITE_P(Extremes, ExtremesFamily, testing::ValuesIn(extremes_families()),
                         [](const testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace tr::bsdf_suite
