// CoreCalls on the GLSL build of core/: a memoizing batch evaluator. The validation library
// calls its callables one at a time; here each call is looked up in a cache of values computed
// by bsdf_probe.comp. A miss records the query and answers with the C++ build's value so the
// check can go on; after the check, every miss is evaluated on the device in one batch and the
// check runs again, until a run misses nothing. The verdict of a check therefore rests on device
// values alone. Queries are keyed by the exact bits of their arguments.
#ifndef TWINRAY_TESTS_BSDF_GPU_GPU_CORE_CALLS_H
#define TWINRAY_TESTS_BSDF_GPU_GPU_CORE_CALLS_H

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core_calls.h"
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
  explicit GpuCoreCalls(ProbeDevice& device) : device_(device) {}

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
  void run_check(const std::function<void()>& check) override;
  static constexpr int kSpeculativeRuns = 4;

  // What was measured since the last call; resets it.
  Lockstep take_lockstep();

 private:
  static constexpr uint32_t kNone = 0xffffffffu;
  static constexpr uint64_t kEmptySlot = ~uint64_t(0);
  // The device's value of q; on a miss, records q and returns cpu(), the C++ build's value.
  template <typename Cpu>
  ProbeResult query(const ProbeQuery& q, Cpu cpu);
  uint32_t find(const ProbeQuery& q) const;
  void index(std::size_t first, std::size_t last);  // adds queries_[first, last) to table_
  uint material_index(const Material& m);
  void evaluate_misses();

  ProbeDevice& device_;
  // Materials live in tests/bsdf's local store (with the children of blends).
  std::map<std::string, uint> material_indices_;  // by the record's bytes
  uint last_material_ = 0;

  // The values of the current check: every query evaluated on the device and its result,
  // found through an open-addressing table of positions.
  std::vector<ProbeQuery> queries_;
  std::vector<ProbeResult> results_;
  std::vector<uint64_t> table_;
  // A check calls in much the same order on every run: the positions the calls of the
  // previous run found (or will find, for misses) are tried in order first, without hashing.
  std::vector<uint32_t> tape_, previous_tape_;
  std::vector<uint32_t> tape_index_;  // position -> its first call in previous_tape_
  std::size_t cursor_ = 0;            // the next call of previous_tape_ to try
  bool immediate_ = false;            // evaluate misses at once (see run_check)
  std::vector<ProbeQuery> misses_;
  std::vector<ProbeResult> predictions_;  // the C++ build's values of misses_
  Lockstep lockstep_;
};

}  // namespace tr::bsdf_gpu

#endif
