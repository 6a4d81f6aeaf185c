// Validation of a BSDF written in GLSL by the user (issue 16): the user's file is wrapped in a
// compute shader, compiled with glslangValidator at run time, evaluated on a Vulkan device
// (lavapipe or a GPU), and its values are fed to the suites of validation/bsdf
// (twinray_validation.h) through their CheckRunner hook. See README.md for the user's contract.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "against.h"
#include "convention.h"
#include "plugin_bsdf.h"
#include "shader_device.h"
#include "shader_source.h"
#include "twinray_validation.h"

namespace tr::shader_bsdf {

namespace validation = twinray::validation;

// What to run: one validate_bsdf() per parameter set of the grid.
struct CheckOptions {
  std::vector<double> incident_theta_degrees = {0.0, 30.0, 60.0, 85.0, 89.9};
  double incident_phi_degrees = 30.0;
  validation::ValidationOptions validation;  // significance: overall, over the whole grid
  bool reciprocal = true;
  Convention convention;  // the user's file's, converted to twinray's
  // --against: compare each parameter set with this plugin (its albedo tests join the Šidák
  // correction of the run).
  const PluginBsdf* against = nullptr;
  AgainstOptions against_options;
};

// Parameter sets: the Cartesian product of the values given per parameter (defaults elsewhere).
std::vector<std::vector<float>> parameter_grid(
    const std::vector<ShaderParameter>& declared,
    const std::map<std::string, std::vector<float>>& values);

// Label of one parameter set, e.g. "alpha=0.3 f0=0.9".
std::string parameter_label(const std::vector<ShaderParameter>& declared,
                            const std::vector<float>& set);

struct CheckOutcome {
  validation::Report report;           // one group of lines per parameter set, named by its label
  std::size_t evaluations = 0;         // device evaluations
  std::size_t batches = 0;             // device dispatches
  std::vector<AgainstResult> against;  // per parameter set, with --against
};

CheckOutcome check_shader_bsdf(ShaderDevice& device, const ShaderSource& source,
                               const std::vector<std::vector<float>>& grid,
                               const CheckOptions& options);

}  // namespace tr::shader_bsdf
