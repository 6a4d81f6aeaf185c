// Convergence records: time-to-error interpolation, fitted rates, CSV and SVG output.
#include "validation/image/convergence.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tr {
namespace {

// An ideal Monte Carlo series: RMSE = 0.1 t^-1/2, relMSE = 0.01 / t, at t = 2^k seconds.
ConvergenceSeries ideal(const std::string& name) {
  ConvergenceSeries s;
  s.name = name;
  for (int k = 0; k <= 10; ++k) {
    double t = std::ldexp(1.0, k);
    s.points.push_back({t, 64.0 * t, 0.1 / std::sqrt(t), 0.01 / t});
  }
  return s;
}

TEST(Convergence, TimeToErrorInterpolatesInLogLog) {
  ConvergenceSeries s = ideal("path");
  // On an exact power law the log-log interpolation is exact: RMSE 0.1 t^-1/2 = 0.01 at 100 s.
  ASSERT_TRUE(time_to_error(s, ConvergenceMetric::rmse, 0.01));
  EXPECT_NEAR(*time_to_error(s, ConvergenceMetric::rmse, 0.01), 100.0, 1e-9);
  EXPECT_NEAR(*time_to_error(s, ConvergenceMetric::relmse, 1e-3), 10.0, 1e-9);
  EXPECT_DOUBLE_EQ(*time_to_error(s, ConvergenceMetric::rmse, 1.0), 1.0);  // already there
  EXPECT_FALSE(time_to_error(s, ConvergenceMetric::relmse, 1e-6));         // never gets there
}

TEST(Convergence, RateOfAnUnbiasedEstimator) {
  ConvergenceSeries s = ideal("path");
  EXPECT_NEAR(*convergence_rate(s, ConvergenceMetric::rmse), -0.5, 1e-12);
  EXPECT_NEAR(*convergence_rate(s, ConvergenceMetric::relmse), -1.0, 1e-12);
  // A biased estimator levels off: its error stops falling and the fitted rate is shallower.
  for (ConvergencePoint& p : s.points) p.rmse = std::hypot(p.rmse, 0.005);
  EXPECT_GT(*convergence_rate(s, ConvergenceMetric::rmse), -0.5);
  ConvergenceSeries one;
  one.points.push_back({1.0, 1.0, 0.1, 0.1});
  EXPECT_FALSE(convergence_rate(one, ConvergenceMetric::rmse));
}

TEST(Convergence, CsvQuotesNamesAndListsEveryPoint) {
  std::string csv = convergence_csv({ideal("path, max_depth 8"), ideal("direct")});
  EXPECT_EQ(
      csv.rfind(
          "series,seconds,spp,rmse,relmse,relmse_stderr,renders,estimated_relmse,seed_relmse\n", 0),
      0u);
  EXPECT_NE(csv.find("\"path, max_depth 8\",1,64,0.1,0.01,0,1,,\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("direct,1024,65536,0.003125,9.765625e-06,0,1,,\n"), std::string::npos) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 11);
}

TEST(Convergence, SvgHasTwoPanelsAndALinePerSeries) {
  std::string svg = convergence_svg({ideal("a & b"), ideal("c")}, "Cornell box");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("data-metric=\"RMSE\""), std::string::npos);
  EXPECT_NE(svg.find("data-metric=\"relMSE\""), std::string::npos);
  size_t lines = 0;
  for (size_t at = svg.find("class=\"series\""); at != std::string::npos;
       at = svg.find("class=\"series\"", at + 1))
    ++lines;
  EXPECT_EQ(lines, 4u);
  EXPECT_NE(svg.find("a &amp; b"), std::string::npos);
  EXPECT_NE(svg.find(">1e-3<"), std::string::npos);  // decade ticks
}

}  // namespace
}  // namespace tr
