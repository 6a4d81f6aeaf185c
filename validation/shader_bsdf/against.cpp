#include "against.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/colormap.h"
#include "validation/image/xml_escape.h"

namespace tr::shader_bsdf {

namespace validation = twinray::validation;

AgainstOptions::AgainstOptions() {
  for (double t = 2.5; t < 90.0; t += 5.0) theta_degrees.push_back(t);
  theta_degrees.push_back(89.0);
}

namespace {

// The largest relative difference over the channels, and whether some channel lies beyond the
// tolerance.
struct Difference {
  double relative = 0.0;
  bool mismatch = false;
};

Difference difference(const glm::vec3& a, const glm::vec3& b, const AgainstOptions& o) {
  Difference d;
  for (int c = 0; c < 3; ++c) {
    const double x = a[c], y = b[c];
    // NaN compares unequal to everything: it is a mismatch of relative size 1.
    if (!(std::isfinite(x) && std::isfinite(y))) {
      d.relative = std::max(d.relative, 1.0);
      d.mismatch = true;
      continue;
    }
    const double scale = std::max(std::abs(x), std::abs(y));
    if (scale > 0.0) d.relative = std::max(d.relative, std::abs(x - y) / scale);
    d.mismatch |= std::abs(x - y) > o.relative_tolerance * scale + o.absolute_tolerance;
  }
  return d;
}

std::string vec(const glm::vec3& v) {
  char s[96];
  if (v.x == v.y && v.y == v.z) {
    std::snprintf(s, sizeof(s), "%.6g", double(v.x));
  } else {
    std::snprintf(s, sizeof(s), "(%.6g, %.6g, %.6g)", double(v.x), double(v.y), double(v.z));
  }
  return s;
}

double theta_of(const glm::vec3& w) {
  return std::acos(std::clamp(double(w.z), -1.0, 1.0)) * 180.0 / M_PI;
}

double phi_of(const glm::vec3& w) {
  double phi = std::atan2(double(w.y), double(w.x)) * 180.0 / M_PI;
  return phi < 0.0 ? phi + 360.0 : phi;
}

std::string where(const AgainstPair& p) {
  char s[160];
  std::snprintf(s, sizeof(s), "theta_i=%.4g theta_o=%.4g phi_o-phi_i=%.4g", theta_of(p.wi),
                theta_of(p.wo), std::fmod(phi_of(p.wo) - phi_of(p.wi) + 360.0, 360.0));
  return s;
}

}  // namespace

AgainstResult compare_against(const validation::BsdfUnderTest& user,
                              const validation::CheckRunner& run,
                              const validation::BsdfUnderTest& reference,
                              const AgainstOptions& options) {
  AgainstResult r;
  r.user = user.name;
  r.reference = reference.name;
  r.theta = options.theta_degrees;
  r.alpha_per_test = options.alpha_per_test;
  r.phi_i = options.phi_i_degrees;
  const std::size_t n = r.theta.size(), steps = std::size_t(std::max(1, options.delta_phi_steps));
  r.eval_difference.assign(n * n, 0.0);
  r.pdf_difference.assign(n * n, 0.0);
  r.eval_beyond_tolerance.assign(n * n, 0);
  auto wi_of = [&](std::size_t i) {
    return validation::direction_from_angles(r.theta[i], options.phi_i_degrees);
  };
  auto wo_of = [&](std::size_t o, std::size_t k) {
    return validation::direction_from_angles(
        r.theta[o], options.phi_i_degrees + 360.0 * double(k) / double(steps));
  };
  std::vector<glm::vec3> user_eval(n * n * steps);
  std::vector<float> user_pdf(n * n * steps);
  run([&] {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t o = 0; o < n; ++o)
        for (std::size_t k = 0; k < steps; ++k) {
          const std::size_t at = (i * n + o) * steps + k;
          user_eval[at] = user.eval(wi_of(i), wo_of(o, k));
          user_pdf[at] = user.pdf(wi_of(i), wo_of(o, k));
        }
  });
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t o = 0; o < n; ++o) {
      for (std::size_t k = 0; k < steps; ++k) {
        const std::size_t at = (i * n + o) * steps + k;
        AgainstPair pair;
        pair.wi = wi_of(i);
        pair.wo = wo_of(o, k);
        ++r.pairs;
        pair.user = user_eval[at];
        pair.reference = reference.eval(pair.wi, pair.wo);
        Difference d = difference(pair.user, pair.reference, options);
        pair.difference = d.relative;
        r.eval_mismatches += d.mismatch;
        r.eval_beyond_tolerance[i * n + o] |= d.mismatch;
        r.eval_difference[i * n + o] = std::max(r.eval_difference[i * n + o], d.relative);
        if (d.relative >= r.worst_eval.difference) r.worst_eval = pair;
        pair.user = glm::vec3(user_pdf[at]);
        pair.reference = glm::vec3(reference.pdf(pair.wi, pair.wo));
        d = difference(pair.user, pair.reference, options);
        pair.difference = d.relative;
        r.pdf_mismatches += d.mismatch;
        r.pdf_difference[i * n + o] = std::max(r.pdf_difference[i * n + o], d.relative);
        if (d.relative >= r.worst_pdf.difference) r.worst_pdf = pair;
      }
    }
  }
  for (double theta : options.albedo_theta_degrees) {
    const glm::vec3 wi = validation::direction_from_angles(theta, options.phi_i_degrees);
    validation::AlbedoResult u, ref;
    run([&] { u = validation::albedo_test(user, wi, options.albedo_samples, options.seed); });
    ref = validation::albedo_test(reference, wi, options.albedo_samples, options.seed + 1);
    AgainstAlbedo a;
    a.theta_i = theta;
    a.user = u.albedo;
    a.user_error = u.standard_error;
    a.reference = ref.albedo;
    a.reference_error = ref.standard_error;
    // Two independent means: z = (a - b) / sqrt(se_a^2 + se_b^2), two-sided p = erfc(|z|/sqrt 2).
    // Bonferroni over the channels that differ in either BSDF (one test for gray albedos).
    const bool gray = a.user.x == a.user.y && a.user.y == a.user.z &&
                      a.reference.x == a.reference.y && a.reference.y == a.reference.z;
    const int channels = gray ? 1 : 3;
    double p_min = 1.0;
    for (int c = 0; c < channels; ++c) {
      const double se = std::hypot(a.user_error[c], a.reference_error[c]);
      const double gap = std::abs(a.user[c] - a.reference[c]);
      const double p = se > 0.0 ? std::erfc(gap / se / std::sqrt(2.0)) : (gap == 0.0 ? 1.0 : 0.0);
      p_min = std::min(p_min, std::isfinite(p) ? p : 0.0);
    }
    a.p_value = std::min(1.0, channels * p_min);
    r.albedo.push_back(a);
  }
  return r;
}

bool AgainstResult::albedo_equal() const {
  for (const AgainstAlbedo& a : albedo)
    if (!(a.p_value >= alpha_per_test)) return false;
  return true;
}

validation::Report AgainstResult::report() const {
  validation::Report report;
  const std::string& name = user;
  auto summary = [&](const char* what, std::size_t mismatches, const AgainstPair& worst) {
    std::ostringstream s;
    s << mismatches << " of " << pairs << " (wi, wo) pairs differ beyond the tolerance; largest "
      << "relative difference " << worst.difference << " at " << where(worst) << ": "
      << vec(worst.user) << " (" << what << ") vs " << vec(worst.reference) << " (" << reference
      << ")";
    return s.str();
  };
  validation::CheckResult eval;
  eval.bsdf = name;
  eval.check = "vs-eval";
  eval.passed = eval_equal();
  eval.detail = summary("yours", eval_mismatches, worst_eval);
  report.checks.push_back(eval);
  validation::CheckResult pdf = eval;
  pdf.check = "vs-pdf";
  pdf.passed = true;
  pdf.detail = summary("yours", pdf_mismatches, worst_pdf) +
               (pdf_mismatches ? " (reported, not a failure: another sampling strategy)" : "");
  report.checks.push_back(pdf);
  for (const AgainstAlbedo& a : albedo) {
    validation::CheckResult line;
    line.bsdf = name;
    line.check = "vs-albedo";
    line.wi = validation::direction_from_angles(a.theta_i, phi_i);
    line.statistical = true;
    line.p_value = a.p_value;
    line.alpha = alpha_per_test;
    line.passed = a.p_value >= alpha_per_test;
    int c = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(a.user[k] - a.reference[k]) > std::abs(a.user[c] - a.reference[c])) c = k;
    char s[200];
    std::snprintf(
        s, sizeof(s), "albedo %.5f +- %.5f (yours) vs %.5f +- %.5f (twinray): %+.3g%%", a.user[c],
        a.user_error[c], a.reference[c], a.reference_error[c],
        a.reference[c] != 0.0 ? 100.0 * (a.user[c] - a.reference[c]) / a.reference[c] : 0.0);
    line.detail = s;
    report.checks.push_back(line);
  }
  return report;
}

std::string against_table(const AgainstResult& r) {
  std::ostringstream s;
  const std::size_t n = r.theta.size();
  s << "eval of " << r.user << " against " << r.reference
    << ": largest relative difference over phi_o per (theta_i row, theta_o column), degrees\n";
  char cell[32];
  s << "theta_i\\o";
  for (double t : r.theta) {
    std::snprintf(cell, sizeof(cell), " %5.1f", t);
    s << cell;
  }
  s << "\n";
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(cell, sizeof(cell), "%9.1f", r.theta[i]);
    s << cell;
    for (std::size_t o = 0; o < n; ++o) {
      const double d = r.eval_difference[i * n + o];
      if (d == 0.0) {
        s << "     0";
      } else {
        std::snprintf(cell, sizeof(cell), " %5.0e", d);
        s << cell;
      }
    }
    s << "\n";
  }
  s << "directional albedo (mean sample weight, +- standard error):\n";
  for (const AgainstAlbedo& a : r.albedo) {
    std::snprintf(cell, sizeof(cell), "%5.1f", a.theta_i);
    s << "  theta_i=" << cell << "  yours " << vec(glm::vec3(a.user)) << " +- "
      << vec(glm::vec3(a.user_error)) << "  twinray " << vec(glm::vec3(a.reference)) << " +- "
      << vec(glm::vec3(a.reference_error)) << "  p=" << a.p_value << "\n";
  }
  return s.str();
}

namespace {

std::string viridis(double t) {
  const std::array<float, 3> rgb = colormap_srgb(Colormap::viridis, float(t));
  char s[16];
  std::snprintf(s, sizeof(s), "#%02x%02x%02x", int(std::lround(255.0f * rgb[0])),
                int(std::lround(255.0f * rgb[1])), int(std::lround(255.0f * rgb[2])));
  return s;
}

}  // namespace

std::string against_heat_map_svg(const AgainstResult& r) {
  // log10 of the relative difference, from 1e-7 (and exact agreement) to 1.
  constexpr double kLow = -7.0, kHigh = 0.0;
  auto shade = [&](double d) { return d > 0.0 ? (std::log10(d) - kLow) / (kHigh - kLow) : 0.0; };
  const std::size_t n = r.theta.size();
  const int cell = 22, left = 70, top = 50, grid = int(n) * cell;
  const int width = left + grid + 110, height = top + grid + 60;
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << left << "\" y=\"18\" font-size=\"13\">eval: " << xml_escape(r.user) << " vs "
    << xml_escape(r.reference) << "</text>\n"
    << "<text x=\"" << left << "\" y=\"34\">largest relative difference over phi_o; "
    << "outlined: beyond the tolerance</text>\n";
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t o = 0; o < n; ++o) {
      const double d = r.eval_difference[i * n + o];
      // theta_i along x, theta_o along y (growing upwards).
      const int x = left + int(i) * cell, y = top + int(n - 1 - o) * cell;
      s << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << cell << "\" height=\"" << cell
        << "\" fill=\"" << viridis(shade(d)) << "\""
        << (r.eval_beyond_tolerance[i * n + o] ? " stroke=\"#e00000\" stroke-width=\"2\"" : "")
        << "><title>theta_i=" << r.theta[i] << " theta_o=" << r.theta[o] << ": " << d
        << "</title></rect>\n";
    }
  }
  for (std::size_t k = 0; k < n; k += 3) {
    s << "<text x=\"" << left + int(k) * cell + cell / 2 << "\" y=\"" << top + grid + 14
      << "\" text-anchor=\"middle\">" << r.theta[k] << "</text>\n";
    s << "<text x=\"" << left - 4 << "\" y=\"" << top + int(n - 1 - k) * cell + cell / 2 + 4
      << "\" text-anchor=\"end\">" << r.theta[k] << "</text>\n";
  }
  s << "<text x=\"" << left + grid / 2 << "\" y=\"" << top + grid + 32
    << "\" text-anchor=\"middle\">theta_i (degrees)</text>\n"
    << "<text x=\"16\" y=\"" << top + grid / 2 << "\" transform=\"rotate(-90 16 " << top + grid / 2
    << ")\" text-anchor=\"middle\">theta_o (degrees)</text>\n";
  // The color bar, one band per decade.
  const int bar_x = left + grid + 30;
  for (int k = 0; k < 7; ++k) {
    const int y = top + k * grid / 7;
    s << "<rect x=\"" << bar_x << "\" y=\"" << y << "\" width=\"16\" height=\"" << grid / 7 + 1
      << "\" fill=\"" << viridis(1.0 - (k + 0.5) / 7.0) << "\"/>\n"
      << "<text x=\"" << bar_x + 20 << "\" y=\"" << y + 4 << "\">1e" << -k << "</text>\n";
  }
  s << "<text x=\"" << bar_x + 20 << "\" y=\"" << top + grid + 4 << "\">&lt;1e-7</text>\n"
    << "</svg>\n";
  return s.str();
}

}  // namespace tr::shader_bsdf
