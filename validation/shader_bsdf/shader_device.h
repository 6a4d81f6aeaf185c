// A compiled check-bsdf wrapper on a Vulkan device (lavapipe or a GPU), and the user's BSDF on it
// as validation/bsdf's callables (twinray_validation.h), fed through their CheckRunner hook: a
// client of validation/device_batch.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "compute_kernel.h"
#include "memoizing_evaluator.h"
#include "twinray_validation.h"

namespace tr::shader_bsdf {

namespace validation = twinray::validation;

// A Vulkan compute pipeline of a compiled wrapper on device `selector` ("" the first usable one,
// an index or a name substring, as `twinray render --device`). Throws GpuError.
class ShaderDevice {
 public:
  ShaderDevice(const std::vector<uint32_t>& spirv, const std::string& selector);
  const std::string& name() const { return kernel_.device_name(); }

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
  void evaluate(const Query* queries, std::size_t count, const std::vector<float>& parameters,
                Result* results);

 private:
  device_batch::ComputeKernel kernel_;
};

// The user's BSDF on a device at one parameter set: the callables of validation/bsdf, answered
// from device values by device_batch's memoizing evaluator; a call not cached yet is answered with
// zeros until its batch is evaluated.
class ShaderBsdf {
 public:
  ShaderBsdf(ShaderDevice& device, std::vector<float> parameters);
  ShaderBsdf(const ShaderBsdf&) = delete;
  ShaderBsdf& operator=(const ShaderBsdf&) = delete;
  validation::BsdfUnderTest under_test(const std::string& name, bool reciprocal);
  void run_check(const std::function<void()>& check) { memo_.run_check(check); }
  std::size_t evaluations() const { return memo_.stats().evaluations; }
  std::size_t batches() const { return memo_.stats().batches; }

 private:
  std::vector<float> parameters_;
  device_batch::MemoizingEvaluator<ShaderDevice::Query, ShaderDevice::Result> memo_;
};

}  // namespace tr::shader_bsdf
