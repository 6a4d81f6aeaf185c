// A compiled check-bsdf wrapper on a Vulkan device (lavapipe or a GPU), and the user's BSDF on it
// as validation/bsdf's callables (twinray_validation.h), fed through their CheckRunner hook.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "twinray_validation.h"

namespace tr::shader_bsdf {

namespace validation = twinray::validation;

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

}  // namespace tr::shader_bsdf
