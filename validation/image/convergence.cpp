#include "validation/image/convergence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "validation/image/xml_escape.h"

namespace tr {

double metric_value(const ConvergencePoint& p, ConvergenceMetric metric) {
  return metric == ConvergenceMetric::rmse ? p.rmse : p.relmse;
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Okabe & Ito, "Color Universal Design" (2008).
const char* kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                          "#E69F00", "#56B4E9", "#F0E442", "#000000"};

bool usable(const ConvergencePoint& p, ConvergenceMetric m) {
  return p.seconds > 0.0 && metric_value(p, m) > 0.0 && std::isfinite(p.seconds) &&
         std::isfinite(metric_value(p, m));
}

// One log-log panel at (x0, y0) of size w x h.
void panel(std::ostringstream& svg, const std::vector<ConvergenceSeries>& series,
           ConvergenceMetric metric, const char* label, double x0, double y0, double w, double h) {
  double tmin = INFINITY, tmax = -INFINITY, emin = INFINITY, emax = -INFINITY;
  for (const ConvergenceSeries& s : series)
    for (const ConvergencePoint& p : s.points)
      if (usable(p, metric)) {
        tmin = std::min(tmin, p.seconds);
        tmax = std::max(tmax, p.seconds);
        emin = std::min(emin, metric_value(p, metric));
        emax = std::max(emax, metric_value(p, metric));
      }
  svg << "<g class=\"panel\" data-metric=\"" << label << "\">\n";
  svg << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << w << "\" height=\"" << h
      << "\" fill=\"none\" stroke=\"#444\"/>\n";
  svg << "<text x=\"" << x0 + w / 2 << "\" y=\"" << y0 + h + 38
      << "\" text-anchor=\"middle\">seconds</text>\n";
  svg << "<text transform=\"translate(" << x0 - 58 << "," << y0 + h / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << label << "</text>\n";
  if (!(tmin <= tmax && emin <= emax)) {
    svg << "<text x=\"" << x0 + w / 2 << "\" y=\"" << y0 + h / 2
        << "\" text-anchor=\"middle\">no data</text>\n</g>\n";
    return;
  }
  // Whole decades around the data.
  double lt0 = std::floor(std::log10(tmin)), lt1 = std::ceil(std::log10(tmax));
  double le0 = std::floor(std::log10(emin)), le1 = std::ceil(std::log10(emax));
  if (lt1 == lt0) lt1 += 1;
  if (le1 == le0) le1 += 1;
  auto X = [&](double t) { return x0 + (std::log10(t) - lt0) / (lt1 - lt0) * w; };
  auto Y = [&](double e) { return y0 + h - (std::log10(e) - le0) / (le1 - le0) * h; };
  for (double d = lt0; d <= lt1; ++d) {
    double x = X(std::pow(10.0, d));
    svg << "<line x1=\"" << x << "\" y1=\"" << y0 << "\" x2=\"" << x << "\" y2=\"" << y0 + h
        << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << y0 + h + 18
        << "\" text-anchor=\"middle\" font-size=\"12\">1e" << int(d) << "</text>\n";
  }
  for (double d = le0; d <= le1; ++d) {
    double y = Y(std::pow(10.0, d));
    svg << "<line x1=\"" << x0 << "\" y1=\"" << y << "\" x2=\"" << x0 + w << "\" y2=\"" << y
        << "\" stroke=\"#ddd\"/><text x=\"" << x0 - 6 << "\" y=\"" << y + 4
        << "\" text-anchor=\"end\" font-size=\"12\">1e" << int(d) << "</text>\n";
  }
  for (size_t i = 0; i < series.size(); ++i) {
    svg << "<polyline class=\"series\" fill=\"none\" stroke-width=\"2\" stroke=\""
        << kColours[i % 8] << "\" points=\"";
    for (const ConvergencePoint& p : series[i].points)
      if (usable(p, metric))
        svg << fmt("%.2f", X(p.seconds)) << "," << fmt("%.2f", Y(metric_value(p, metric))) << " ";
    svg << "\"/>\n";
  }
  svg << "</g>\n";
}

}  // namespace

std::string convergence_csv(const std::vector<ConvergenceSeries>& series) {
  std::string out =
      "series,seconds,spp,rmse,relmse,relmse_stderr,renders,estimated_relmse,seed_relmse\n";
  for (const ConvergenceSeries& s : series)
    for (const ConvergencePoint& p : s.points)
      out += csv_field(s.name) + "," + fmt("%.9g", p.seconds) + "," + fmt("%.9g", p.spp) + "," +
             fmt("%.9g", p.rmse) + "," + fmt("%.9g", p.relmse) + "," +
             fmt("%.9g", p.relmse_stderr) + "," + std::to_string(p.renders) + "," +
             (p.renders > 1 ? fmt("%.9g", p.estimated_relmse) + "," + fmt("%.9g", p.seed_relmse)
                            : std::string(",")) +
             "\n";
  return out;
}

std::string convergence_svg(const std::vector<ConvergenceSeries>& series,
                            const std::string& title) {
  const double width = 1000, panel_w = 380, panel_h = 300, top = 60, left = 90;
  const double legend_top = top + panel_h + 70, height = legend_top + 22.0 * series.size() + 20;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"14\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n<text x=\""
      << width / 2 << "\" y=\"30\" text-anchor=\"middle\" font-size=\"18\">" << xml_escape(title)
      << "</text>\n";
  panel(svg, series, ConvergenceMetric::rmse, "RMSE", left, top, panel_w, panel_h);
  panel(svg, series, ConvergenceMetric::relmse, "relMSE", left + panel_w + 120, top, panel_w,
        panel_h);
  for (size_t i = 0; i < series.size(); ++i) {
    double y = legend_top + 22.0 * i;
    svg << "<line x1=\"" << left << "\" y1=\"" << y - 5 << "\" x2=\"" << left + 30 << "\" y2=\""
        << y - 5 << "\" stroke-width=\"3\" stroke=\"" << kColours[i % 8] << "\"/><text x=\""
        << left + 40 << "\" y=\"" << y << "\">" << xml_escape(series[i].name) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

std::optional<double> time_to_error(const ConvergenceSeries& series, ConvergenceMetric metric,
                                    double target) {
  const ConvergencePoint* previous = nullptr;
  for (const ConvergencePoint& p : series.points) {
    if (!usable(p, metric)) continue;
    double e = metric_value(p, metric);
    if (e <= target) {
      if (!previous) return p.seconds;
      double e0 = metric_value(*previous, metric);
      double f = (std::log(target) - std::log(e0)) / (std::log(e) - std::log(e0));
      return std::exp(std::log(previous->seconds) +
                      f * (std::log(p.seconds) - std::log(previous->seconds)));
    }
    previous = &p;
  }
  return std::nullopt;
}

std::optional<double> convergence_rate(const ConvergenceSeries& series, ConvergenceMetric metric) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ConvergencePoint& p : series.points) {
    if (!usable(p, metric)) continue;
    double x = std::log(p.seconds), y = std::log(metric_value(p, metric));
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  double denominator = n * sxx - sx * sx;
  if (n < 2 || denominator <= 0.0) return std::nullopt;
  return (n * sxy - sx * sy) / denominator;
}

}  // namespace tr
