#include "shader_bsdf.h"

#include <sstream>

namespace tr::shader_bsdf {

// ---- The suites over a grid -----------------------------------------------------------

std::vector<std::vector<float>> parameter_grid(
    const std::vector<ShaderParameter>& declared,
    const std::map<std::string, std::vector<float>>& values) {
  std::vector<std::vector<float>> grid(1);
  for (const ShaderParameter& p : declared) {
    auto it = values.find(p.name);
    std::vector<float> choices =
        it == values.end() ? std::vector<float>{p.default_value} : it->second;
    std::vector<std::vector<float>> next;
    for (const std::vector<float>& partial : grid) {
      for (float v : choices) {
        next.push_back(partial);
        next.back().push_back(v);
      }
    }
    grid = std::move(next);
  }
  return grid;
}

std::string parameter_label(const std::vector<ShaderParameter>& declared,
                            const std::vector<float>& set) {
  std::ostringstream s;
  for (std::size_t i = 0; i < declared.size(); ++i)
    s << (i ? " " : "") << declared[i].name << "=" << set[i];
  return declared.empty() ? std::string("(no parameters)") : s.str();
}

CheckOutcome check_shader_bsdf(ShaderDevice& device, const ShaderSource& source,
                               const std::vector<std::vector<float>>& grid,
                               const CheckOptions& options) {
  std::vector<glm::vec3> incident;
  for (double theta : options.incident_theta_degrees)
    incident.push_back(validation::direction_from_angles(theta, options.incident_phi_degrees));
  CheckOutcome outcome;
  for (const std::vector<float>& set : grid) {
    ShaderBsdf bsdf(device, set);
    const validation::BsdfUnderTest under_test = in_twinray_convention(
        bsdf.under_test(parameter_label(source.parameters, set), options.reciprocal),
        options.convention);
    validation::ValidationOptions o = options.validation;
    // Šidák over every statistical test of the grid: a correct BSDF fails the whole run with
    // probability `significance`.
    const std::size_t against_tests =
        options.against ? options.against_options.albedo_theta_degrees.size() : 0;
    o.alpha_per_test = validation::sidak_alpha(
        o.significance,
        (validation::statistical_test_count(under_test, incident.size()) + against_tests) *
            grid.size());
    o.run_check = [&bsdf](const std::function<void()>& check) { bsdf.run_check(check); };
    outcome.report.append(validation::validate_bsdf(under_test, incident, o));
    if (options.against) {
      AgainstOptions a = options.against_options;
      a.alpha_per_test = o.alpha_per_test;
      outcome.against.push_back(
          compare_against(under_test, o.run_check, options.against->under_test(), a));
      outcome.report.append(outcome.against.back().report());
    }
    // validation/bsdf's checks pass a sample() whose every draw fails (nothing is binned and
    // nothing is weighed); a user's BSDF must succeed at least once in kDraws stratified draws at
    // every incident direction above the horizon.
    constexpr int kDraws = 32;
    for (const glm::vec3& wi : incident) {
      if (!(wi.z > 0.0f)) continue;
      int succeeded = 0;
      bsdf.run_check([&] {
        succeeded = 0;
        for (int a = 0; a < kDraws; ++a) {
          for (int b = 0; b < kDraws; ++b) {
            glm::vec2 u2((a + 0.5f) / kDraws, (b + 0.5f) / kDraws);
            succeeded += under_test.sample(wi, u2.x, u2).pdf > 0.0f ? 1 : 0;
          }
        }
      });
      validation::CheckResult line;
      line.bsdf = under_test.name;
      line.check = "draws";
      line.wi = wi;
      line.passed = succeeded > 0;
      line.detail = std::to_string(succeeded) + " of " + std::to_string(kDraws * kDraws) +
                    " stratified draws succeeded (pdf > 0)";
      outcome.report.checks.push_back(line);
    }
    outcome.evaluations += bsdf.evaluations();
    outcome.batches += bsdf.batches();
  }
  return outcome;
}

}  // namespace tr::shader_bsdf
