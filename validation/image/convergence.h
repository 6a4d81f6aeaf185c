// Error against time for render variants: CSV, a log-log SVG plot of RMSE and relMSE against
// seconds, time-to-error and the fitted convergence rate (the building blocks of
// `twinray converge`).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tr {

// One rung of a convergence series: the mean over `renders` independent renders (seeds) of
// the same spp, with the standard error of that mean relMSE (0 for one render).
struct ConvergencePoint {
  double seconds = 0.0;
  double spp = 0.0;
  double rmse = 0.0;
  double relmse = 0.0;
  double relmse_stderr = 0.0;
  int renders = 1;
  // With two or more renders (error_calibration.h): the relMSE the renders' variance outputs
  // claim and the one observed among them.
  double estimated_relmse = 0.0;
  double seed_relmse = 0.0;
};

struct ConvergenceSeries {
  std::string name;                      // the variant, e.g. "path, max_depth 8, cpu"
  std::vector<ConvergencePoint> points;  // in order of increasing time
};

enum class ConvergenceMetric { rmse, relmse };

double metric_value(const ConvergencePoint& p, ConvergenceMetric metric);

// Columns: series,seconds,spp,rmse,relmse,relmse_stderr,renders,estimated_relmse,seed_relmse
// (RFC 4180 quoting of the series name; the last two empty for a single render).
std::string convergence_csv(const std::vector<ConvergenceSeries>& series);

// Two log-log panels (RMSE and relMSE against seconds), one line per series, Okabe–Ito
// colour-blind-safe colours. Points with non-positive time or error are left out.
std::string convergence_svg(const std::vector<ConvergenceSeries>& series, const std::string& title);

// The first time the metric reaches `target` or below, interpolated linearly in log(error)
// against log(time) between the two points that bracket the crossing; the first point's time
// when it is already there; nothing when the series never gets there.
std::optional<double> time_to_error(const ConvergenceSeries& series, ConvergenceMetric metric,
                                    double target);

// Least-squares slope of log(error) against log(seconds) over the points with positive values:
// -0.5 for the RMSE and -1 for relMSE of an unbiased Monte Carlo estimator whose cost is
// proportional to the sample count. Nothing with fewer than two usable points.
std::optional<double> convergence_rate(const ConvergenceSeries& series, ConvergenceMetric metric);

}  // namespace tr
