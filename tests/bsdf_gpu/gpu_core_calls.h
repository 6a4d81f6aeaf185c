// CoreCalls on the GLSL build of core/: validation/device_batch's memoizing evaluator over
// bsdf_probe.comp. The validation library calls its callables one at a time; each call is looked
// up in a cache of device values. A miss records the query and answers with the C++ build's value
// so the check can go on; after the check, every miss is evaluated on the device in one batch and
// the check runs again, until a run misses nothing. The verdict of a check therefore rests on
// device values alone. Every evaluated batch is compared with the C++ values it replaced.
#ifndef TWINRAY_TESTS_BSDF_GPU_GPU_CORE_CALLS_H
#define TWINRAY_TESTS_BSDF_GPU_GPU_CORE_CALLS_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core_calls.h"
#include "memoizing_evaluator.h"
#include "probe_device.h"

namespace tr::bsdf_gpu {

// How the device's values compare with the C++ build's at the same arguments (every batched
// query is computed both ways), and what evaluating them cost. Relative differences are
// |a - b| / max(|a|, |b|, 1e-6); samples of different lobes are counted, not compared.
struct Lockstep {
  std::size_t queries = 0;             // evaluated on the device
  std::size_t batches = 0;             // device dispatches
  std::size_t max_runs = 0;            // most runs one check needed
  std::size_t immediate = 0;           // evaluated one by one, in a run past kSpeculativeRuns
  std::size_t lobe_mismatch = 0;       // samples whose lobe (or success) differs
  double max_direction = 0.0;          // max |component difference| of sampled directions/points
  double max_pdf = 0.0;                // max relative difference of densities
  double max_value = 0.0;              // max relative difference of weights and evals
  std::string worst_pdf, worst_value;  // the queries behind the two maxima
  std::size_t beyond_1e3 = 0;          // values whose relative difference exceeds 1e-3
  std::size_t non_finite = 0;          // NaN or Inf in a device result
  std::string first_non_finite;        // the query behind the first one
  double device_seconds = 0.0;         // in ProbeDevice::evaluate
  void merge(const Lockstep& other);
  std::string differences() const;  // one line: the maxima and counts
  std::string summary() const;
};

class GpuCoreCalls : public bsdf_suite::CoreCalls {
 public:
  explicit GpuCoreCalls(ProbeDevice& device);

  vec3 warp_direction(bsdf_suite::Warp w, float parameter, vec2 u) override;
  float warp_direction_pdf(bsdf_suite::Warp w, float parameter, vec3 d) override;
  vec2 warp_point(bsdf_suite::Warp w, vec2 u) override;
  float warp_point_pdf(bsdf_suite::Warp w, vec2 p) override;
  vec3 microfacet_sample(Microfacet d, vec3 wi, vec2 u) override;
  float microfacet_pdf(Microfacet d, vec3 wi, vec3 m) override;
  BsdfSample bsdf_sample(const Material& m, vec2 uv, vec3 wi, float u1, vec2 u2) override;
  float bsdf_pdf(const Material& m, vec2 uv, vec3 wi, vec3 wo) override;
  vec3 bsdf_eval(const Material& m, vec2 uv, vec3 wi, vec3 wo) override;

  // Repeats `check` until a run finds every value in the cache. Adaptive checks (the chi-square
  // quadrature refines where the values say so) may keep asking for new values run after run;
  // past kSpeculativeRuns, each miss is evaluated on the device at once instead of predicted,
  // so that run completes on device values alone.
  void run_check(const std::function<void()>& check) override { memo_.run_check(check); }
  static constexpr int kSpeculativeRuns = 4;

  // What was measured since the last call; resets it.
  Lockstep take_lockstep();

 private:
  uint material_index(const Material& m);
  // Adds a batch's device values, beside the C++ values they replace, to lockstep_.
  void compare(const ProbeQuery* queries, const ProbeResult* gpu, const ProbeResult* cpu,
               std::size_t count);

  // Materials live in tests/bsdf's local store (with the children of blends).
  std::map<std::string, uint> material_indices_;  // by the record's bytes
  uint last_material_ = 0;
  device_batch::MemoizingEvaluator<ProbeQuery, ProbeResult> memo_;
  Lockstep lockstep_;  // the comparisons; take_lockstep() adds the evaluator's counts
};

}  // namespace tr::bsdf_gpu

#endif
