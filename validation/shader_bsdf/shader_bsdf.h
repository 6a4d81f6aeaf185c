// Validation of a BSDF written in GLSL by the user (issue 16): the user's file is wrapped in a
// compute shader, compiled with glslangValidator at run time, evaluated on a Vulkan device
// (lavapipe or a GPU), and its values are fed to the suites of validation/bsdf
// (twinray_validation.h) through their CheckRunner hook. See README.md for the user's contract.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "twinray_validation.h"

namespace tr::shader_bsdf {

namespace validation = twinray::validation;

// The shader does not compile: `message` holds glslang's errors, each as "FILE:LINE: what".
struct ShaderCompileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A parameter the user's file declares with `#pragma twinray_param NAME DEFAULT`.
struct ShaderParameter {
  std::string name;
  float default_value = 0.0f;
};

// The user's file, read and scanned for its parameter declarations. Throws std::runtime_error
// "FILE:LINE: what" for an unreadable file or a malformed declaration.
struct ShaderSource {
  std::string path;
  std::string text;
  std::vector<ShaderParameter> parameters;  // in declaration order
  bool hlsl = false;                        // FILE.hlsl: glslang's HLSL front end
};
ShaderSource read_shader_source(const std::string& path);

// The generated compute shader around the user's file (exposed for the README and tests).
std::string wrapper_source(const ShaderSource& source, const std::string& include_name);

// Compiles the wrapped file to SPIR-V (vulkan1.2) with glslangValidator (the path configured at
// build time, or $TWINRAY_GLSLANG_VALIDATOR). Throws ShaderCompileError with glslang's errors.
std::vector<uint32_t> compile_shader(const ShaderSource& source);

class ShaderDevice;

// The user's BSDF on a device at one parameter set: the callables of validation/bsdf, answered
// from a cache of device values. A call whose arguments are not cached yet is recorded and
// answered with zeros; run_check() repeats a check, evaluating the recorded calls in one batch
// between runs, until a run finds every value in the cache, so the verdict rests on device values
// alone (the values are deterministic, so each run follows the true path one step further).
class ShaderBsdf {
 public:
  ShaderBsdf(ShaderDevice& device, std::vector<float> parameters);
  ~ShaderBsdf();
  validation::BsdfUnderTest under_test(const std::string& name, bool reciprocal);
  void run_check(const std::function<void()>& check);
  std::size_t evaluations() const { return evaluations_; }
  std::size_t batches() const { return batches_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  ShaderDevice& device_;
  std::vector<float> parameters_;
  std::size_t evaluations_ = 0, batches_ = 0;
};

// A Vulkan compute pipeline of a compiled wrapper on device `selector` ("" the first usable one,
// an index or a name substring, as `twinray render --device`). Throws GpuError.
class ShaderDevice {
 public:
  ShaderDevice(const std::vector<uint32_t>& spirv, const std::string& selector);
  ~ShaderDevice();
  ShaderDevice(const ShaderDevice&) = delete;
  ShaderDevice& operator=(const ShaderDevice&) = delete;
  const std::string& name() const;

  // One query of the wrapper: op 0 sample (arg = u), 1 pdf (arg = wo), 2 eval (arg = wo).
  struct Query {
    uint32_t op, pad0, pad1, pad2;
    float wi[4];
    float arg[4];
  };
  struct Result {
    float wo_pdf[4];  // sample: wo and pdf; pdf: pdf in [3]
    float value[4];   // sample: weight; eval: f |cos theta_o|
  };
  void evaluate(const std::vector<Query>& queries, const std::vector<float>& parameters,
                std::vector<Result>& results);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// What to run: one validate_bsdf() per parameter set of the grid.
struct CheckOptions {
  std::vector<double> incident_theta_degrees = {0.0, 30.0, 60.0, 85.0, 89.9};
  double incident_phi_degrees = 30.0;
  validation::ValidationOptions validation;  // significance: overall, over the whole grid
  bool reciprocal = true;
};

// Parameter sets: the Cartesian product of the values given per parameter (defaults elsewhere).
std::vector<std::vector<float>> parameter_grid(
    const std::vector<ShaderParameter>& declared,
    const std::map<std::string, std::vector<float>>& values);

// Label of one parameter set, e.g. "alpha=0.3 f0=0.9".
std::string parameter_label(const std::vector<ShaderParameter>& declared,
                            const std::vector<float>& set);

struct CheckOutcome {
  validation::Report report;    // one group of lines per parameter set, named by its label
  std::size_t evaluations = 0;  // device evaluations
  std::size_t batches = 0;      // device dispatches
};

CheckOutcome check_shader_bsdf(ShaderDevice& device, const ShaderSource& source,
                               const std::vector<std::vector<float>>& grid,
                               const CheckOptions& options);

}  // namespace tr::shader_bsdf
