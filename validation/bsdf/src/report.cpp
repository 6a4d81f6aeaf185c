// validate_bsdf(): every check of one BSDF at a list of incident directions, as a report.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "twinray_validation.h"

namespace twinray::validation {
namespace {

constexpr double kDegrees = 57.295779513082320876798154814105;

std::string chi_square_detail(const ChiSquareResult& r) {
  std::ostringstream s;
  s << std::setprecision(4);
  if (!r.failure.empty()) s << "FAILURE: " << r.failure << "; ";
  s << "X2=" << r.statistic << " dof=" << r.dof << " int_pdf=" << std::setprecision(6)
    << r.pdf_integral << "+-" << std::setprecision(2) << r.integration_error
    << " failed=" << r.failed_samples << "/" << r.samples;
  if (r.delta_samples > 0) s << " delta=" << r.delta_samples << " in " << r.delta_atoms << " atoms";
  return s.str();
}

std::string consistency_detail(const ConsistencyResult& r) {
  std::ostringstream s;
  s << r.checked_samples << " draws";
  auto count = [&](std::size_t n, const char* what) {
    if (n > 0) s << ", " << n << " " << what;
  };
  count(r.weight_mismatch, "weight!=eval/pdf");
  count(r.pdf_mismatch, "pdf!=sampled pdf");
  count(r.failed_with_weight, "failed draws with weight");
  count(r.not_unit, "non-unit wo");
  count(r.eval_without_pdf, "eval>0 with pdf=0");
  count(r.not_reciprocal, "non-reciprocal");
  count(r.delta_mismatch, "inconsistent delta probabilities");
  if (!r.first_failure.empty()) s << "; first: " << r.first_failure;
  return s.str();
}

}  // namespace

glm::vec3 direction_from_angles(double theta_degrees, double phi_degrees) {
  double theta = theta_degrees / kDegrees, phi = phi_degrees / kDegrees;
  return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                   float(std::cos(theta)));
}

CheckResult report_line(const std::string& name, const glm::vec3& wi, const ChiSquareResult& result,
                        double alpha) {
  CheckResult c;
  c.bsdf = name;
  c.check = "chi2";
  c.wi = wi;
  c.statistical = true;
  c.p_value = result.p_value;
  c.alpha = alpha;
  c.passed = result.failure.empty() && result.p_value >= alpha;
  c.detail = chi_square_detail(result);
  return c;
}

CheckResult report_line(const std::string& name, const glm::vec3& wi, const AlbedoResult& result,
                        double alpha) {
  CheckResult c;
  c.bsdf = name;
  c.check = "albedo";
  c.wi = wi;
  c.statistical = true;
  c.p_value = result.p_value;
  c.alpha = alpha;
  c.passed = result.p_value >= alpha;
  std::ostringstream s;
  s << std::setprecision(5) << "albedo=(" << result.albedo.x << ", " << result.albedo.y << ", "
    << result.albedo.z << ") se=(" << std::setprecision(2) << result.standard_error.x << ", "
    << result.standard_error.y << ", " << result.standard_error.z << ")";
  c.detail = s.str();
  return c;
}

CheckResult report_line(const std::string& name, const glm::vec3& wi,
                        const ConsistencyResult& result) {
  CheckResult c;
  c.bsdf = name;
  c.check = "consistency";
  c.wi = wi;
  c.passed = result.passed();
  c.detail = consistency_detail(result);
  return c;
}

CheckResult report_line(const std::string& name, const ExtremesResult& result) {
  CheckResult c;
  c.bsdf = name;
  c.check = "extremes";
  c.passed = result.failures == 0;
  c.detail =
      std::to_string(result.failures) + " bad of " + std::to_string(result.evaluations) + " values";
  if (!result.first_failure.empty()) c.detail += "; first: " + result.first_failure;
  return c;
}

std::size_t statistical_test_count(const BsdfUnderTest& bsdf, std::size_t incident_directions) {
  bool albedo = bsdf.eval && bsdf.energy_conserving;
  return incident_directions * (albedo ? 2 : 1);
}

Report validate_bsdf(const BsdfUnderTest& bsdf, const std::vector<glm::vec3>& incident,
                     const ValidationOptions& o) {
  double alpha = o.alpha_per_test > 0.0
                     ? o.alpha_per_test
                     : sidak_alpha(o.significance, statistical_test_count(bsdf, incident.size()));
  auto run = [&o](const std::function<void()>& check) {
    if (o.run_check)
      o.run_check(check);
    else
      check();
  };
  Report report;
  std::uint64_t k = 0;
  for (const glm::vec3& wi : incident) {
    ++k;
    ChiSquareOptions chi = o.chi_square;
    chi.seed = o.chi_square.seed + 1000003 * k;
    ChiSquareResult chi_result;
    run([&] { chi_result = chi_square_bsdf(bsdf, wi, chi); });
    report.checks.push_back(report_line(bsdf.name, wi, chi_result, alpha));
    ConsistencyOptions co = o.consistency;
    co.seed = o.consistency.seed + 1000003 * k;
    ConsistencyResult consistency;
    run([&] { consistency = consistency_check(bsdf, wi, co); });
    report.checks.push_back(report_line(bsdf.name, wi, consistency));
    if (bsdf.eval && bsdf.energy_conserving) {
      AlbedoResult a;
      run([&] { a = albedo_test(bsdf, wi, o.albedo_samples, o.chi_square.seed + 7919 * k); });
      report.checks.push_back(report_line(bsdf.name, wi, a, alpha));
    }
  }
  std::vector<glm::vec3> extreme = extreme_incident_directions();
  extreme.insert(extreme.end(), incident.begin(), incident.end());
  ExtremesResult extremes;
  run([&] { extremes = extremes_check(bsdf, extreme, o.extreme_random_draws, o.chi_square.seed); });
  report.checks.push_back(report_line(bsdf.name, extremes));
  return report;
}

bool Report::passed() const {
  for (const CheckResult& c : checks) {
    if (!c.passed) return false;
  }
  return true;
}

void Report::append(const Report& other) {
  checks.insert(checks.end(), other.checks.begin(), other.checks.end());
}

void Report::print(std::ostream& out) const {
  std::ios_base::fmtflags flags = out.flags();
  std::streamsize precision = out.precision();
  out << std::left << std::setw(5) << "ok" << std::setw(12) << "check" << std::setw(44) << "case"
      << std::right << std::setw(9) << "theta_i" << std::setw(8) << "phi_i" << std::setw(12)
      << "p-value" << std::setw(11) << "alpha"
      << "  details\n";
  for (const CheckResult& c : checks) {
    double theta = std::acos(std::clamp(double(c.wi.z), -1.0, 1.0)) * kDegrees;
    double phi = std::atan2(double(c.wi.y), double(c.wi.x)) * kDegrees;
    out << std::left << std::setw(5) << (c.passed ? "ok" : "FAIL") << std::setw(12) << c.check
        << std::setw(44) << c.bsdf << std::right << std::fixed << std::setprecision(3);
    if (c.wi == glm::vec3(0.0f)) {
      out << std::setw(9) << "-" << std::setw(8) << "-";
    } else {
      out << std::setw(9) << theta << std::setw(8) << std::setprecision(1) << phi;
    }
    out.unsetf(std::ios_base::floatfield);
    out << std::setprecision(4);
    if (c.statistical) {
      out << std::setw(12) << c.p_value << std::setw(11) << c.alpha;
    } else {
      out << std::setw(12) << "-" << std::setw(11) << "-";
    }
    out << "  " << c.detail << "\n";
  }
  out.flags(flags);
  out.precision(precision);
}

}  // namespace twinray::validation
