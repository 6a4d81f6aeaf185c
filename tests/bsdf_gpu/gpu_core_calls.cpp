#include "gpu_core_calls.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "core/scene_types.h"
#include "scene_access_local.h"

namespace tr::bsdf_gpu {
namespace {

using bsdf_suite::cpu_core_calls;
using bsdf_suite::Warp;

ProbeQuery make_query(uint op, uint subject, vec4 a, vec4 b = vec4(0.0f), vec4 c = vec4(0.0f)) {
  ProbeQuery q;
  std::memset(&q, 0, sizeof(q));
  q.op = op;
  q.subject = subject;
  q.a = a;
  q.b = b;
  q.c = c;
  return q;
}

ProbeResult make_result(vec3 wo, float pdf, vec3 value, float eta, uint lobe) {
  ProbeResult r;
  std::memset(&r, 0, sizeof(r));
  r.wo_pdf = vec4(wo, pdf);
  r.value_eta = vec4(value, eta);
  r.lobe = lobe;
  return r;
}

ProbeResult pdf_result(float pdf) { return make_result(vec3(0.0f), pdf, vec3(0.0f), 1.0f, 0u); }

uint microfacet_flags(const Microfacet& d) {
  return (d.beckmann ? PROBE_MICROFACET_BECKMANN : 0u) |
         (d.sample_visible ? PROBE_MICROFACET_VISIBLE : 0u);
}

// |a - b| / max(|a|, |b|, 1e-6): relative, with densities and values below 1e-6 compared
// absolutely.
double relative(double a, double b) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-6});
}

bool finite(const ProbeResult& r) {
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(r.wo_pdf[i]) || !std::isfinite(r.value_eta[i])) return false;
  }
  return true;
}

std::string describe(const ProbeQuery& q) {
  std::ostringstream s;
  s << "op " << q.op << " subject " << q.subject << " a=(" << q.a.x << ", " << q.a.y << ", "
    << q.a.z << ", " << q.a.w << ") b=(" << q.b.x << ", " << q.b.y << ", " << q.b.z << ") c=("
    << q.c.x << ", " << q.c.y << ", " << q.c.z << ")";
  return s.str();
}

}  // namespace

static_assert(sizeof(ProbeQuery) == 64 && sizeof(ProbeResult) == 48, "std430 layout");
static_assert(uint(Warp::cosine_hemisphere) == PROBE_WARP_COSINE_HEMISPHERE &&
                  uint(Warp::uniform_sphere) == PROBE_WARP_UNIFORM_SPHERE &&
                  uint(Warp::uniform_hemisphere) == PROBE_WARP_UNIFORM_HEMISPHERE &&
                  uint(Warp::uniform_cone) == PROBE_WARP_UNIFORM_CONE &&
                  uint(Warp::disk_concentric) == PROBE_WARP_DISK_CONCENTRIC &&
                  uint(Warp::triangle) == PROBE_WARP_TRIANGLE,
              "probe.h and tests/bsdf/core_calls.h number the warps alike");

void Lockstep::merge(const Lockstep& o) {
  if (non_finite == 0 && o.non_finite > 0) first_non_finite = o.first_non_finite;
  queries += o.queries;
  batches += o.batches;
  max_passes = std::max(max_passes, o.max_passes);
  lobe_mismatch += o.lobe_mismatch;
  max_direction = std::max(max_direction, o.max_direction);
  max_pdf = std::max(max_pdf, o.max_pdf);
  max_value = std::max(max_value, o.max_value);
  beyond_1e3 += o.beyond_1e3;
  non_finite += o.non_finite;
  device_seconds += o.device_seconds;
}

std::string Lockstep::summary() const {
  std::ostringstream s;
  s << queries << " device evaluations in " << batches << " batches (" << device_seconds
    << " s on the device, at most " << max_passes << " runs per check); GPU vs C++ at the same "
    << "arguments: max |d direction| " << max_direction << ", max rel d pdf " << max_pdf
    << ", max rel d weight/eval " << max_value << ", " << beyond_1e3
    << " values off by > 1e-3 relative, " << lobe_mismatch << " samples of another lobe, "
    << non_finite << " NaN/Inf";
  if (non_finite > 0) s << " (first: " << first_non_finite << ")";
  return s.str();
}

namespace {

uint64_t hash_of(const ProbeQuery& q) {
  // FNV-1a over the words, then the splitmix64 finalizer.
  uint32_t words[sizeof(ProbeQuery) / 4];
  std::memcpy(words, &q, sizeof(q));
  uint64_t h = 1469598103934665603ull;
  for (uint32_t w : words) h = (h ^ w) * 1099511628211ull;
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

bool same(const ProbeQuery& a, const ProbeQuery& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

}  // namespace

uint32_t GpuCoreCalls::find(const ProbeQuery& q) const {
  if (table_.empty()) return kNone;
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = hash_of(q) & mask;; slot = (slot + 1) & mask) {
    uint32_t p = table_[slot];
    if (p == kNone || same(queries_[p], q)) return p;
  }
}

void GpuCoreCalls::insert(uint32_t position) {
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = hash_of(queries_[position]) & mask;; slot = (slot + 1) & mask) {
    uint32_t& p = table_[slot];
    if (p == kNone) {
      p = position;
      return;
    }
    if (same(queries_[p], queries_[position])) return;  // a duplicate keeps the first
  }
}

template <typename Cpu>
ProbeResult GpuCoreCalls::query(const ProbeQuery& q, Cpu cpu) {
  const std::size_t call = tape_.size();
  if (call < previous_tape_.size()) {
    uint32_t p = previous_tape_[call];
    if (p < queries_.size() && same(queries_[p], q)) {
      tape_.push_back(p);
      return results_[p];
    }
  }
  uint32_t p = find(q);
  if (p != kNone) {
    tape_.push_back(p);
    return results_[p];
  }
  // After evaluate_misses() this query sits at queries_.size() + its index among the misses.
  tape_.push_back(uint32_t(queries_.size() + misses_.size()));
  misses_.push_back(q);
  predictions_.push_back(cpu());
  return predictions_.back();
}

uint GpuCoreCalls::material_index(const Material& m) {
  std::string bytes(reinterpret_cast<const char*>(&m), sizeof(Material));
  auto it = material_indices_.find(bytes);
  if (it != material_indices_.end()) return it->second;
  materials_.push_back(m);
  uint index = uint(materials_.size() - 1);
  material_indices_.emplace(bytes, index);
  return index;
}

vec3 GpuCoreCalls::warp_direction(Warp w, float parameter, vec2 u) {
  ProbeQuery q = make_query(PROBE_WARP_DIRECTION, uint(w), vec4(u, parameter, 0.0f));
  return vec3(query(q, [&] {
                return make_result(cpu_core_calls().warp_direction(w, parameter, u), 0.0f,
                                   vec3(0.0f), 1.0f, 0u);
              }).wo_pdf);
}

float GpuCoreCalls::warp_direction_pdf(Warp w, float parameter, vec3 d) {
  ProbeQuery q = make_query(PROBE_WARP_DIRECTION_PDF, uint(w), vec4(d, parameter));
  return query(q, [&] { return pdf_result(cpu_core_calls().warp_direction_pdf(w, parameter, d)); })
      .wo_pdf.w;
}

vec2 GpuCoreCalls::warp_point(Warp w, vec2 u) {
  ProbeQuery q = make_query(PROBE_WARP_POINT, uint(w), vec4(u, 0.0f, 0.0f));
  return vec2(query(q, [&] {
                return make_result(vec3(cpu_core_calls().warp_point(w, u), 0.0f), 0.0f, vec3(0.0f),
                                   1.0f, 0u);
              }).wo_pdf);
}

float GpuCoreCalls::warp_point_pdf(Warp w, vec2 p) {
  ProbeQuery q = make_query(PROBE_WARP_POINT_PDF, uint(w), vec4(p, 0.0f, 0.0f));
  return query(q, [&] { return pdf_result(cpu_core_calls().warp_point_pdf(w, p)); }).wo_pdf.w;
}

vec3 GpuCoreCalls::microfacet_sample(Microfacet d, vec3 wi, vec2 u) {
  ProbeQuery q =
      make_query(PROBE_MICROFACET_SAMPLE, microfacet_flags(d),
                 vec4(d.alpha_u, d.alpha_v, 0.0f, 0.0f), vec4(wi, 0.0f), vec4(u, 0.0f, 0.0f));
  return vec3(query(q, [&] {
                return make_result(cpu_core_calls().microfacet_sample(d, wi, u), 0.0f, vec3(0.0f),
                                   1.0f, 0u);
              }).wo_pdf);
}

float GpuCoreCalls::microfacet_pdf(Microfacet d, vec3 wi, vec3 m) {
  ProbeQuery q = make_query(PROBE_MICROFACET_PDF, microfacet_flags(d),
                            vec4(d.alpha_u, d.alpha_v, 0.0f, 0.0f), vec4(wi, 0.0f), vec4(m, 0.0f));
  return query(q, [&] { return pdf_result(cpu_core_calls().microfacet_pdf(d, wi, m)); }).wo_pdf.w;
}

BsdfSample GpuCoreCalls::bsdf_sample(const Material& m, vec2 uv, vec3 wi, float u1, vec2 u2) {
  ProbeQuery q = make_query(PROBE_BSDF_SAMPLE, material_index(m), vec4(uv, u1, 0.0f),
                            vec4(wi, 0.0f), vec4(u2, 0.0f, 0.0f));
  ProbeResult r = query(q, [&] {
    BsdfSample s = cpu_core_calls().bsdf_sample(m, uv, wi, u1, u2);
    return make_result(s.wo, s.pdf, s.weight, s.eta, s.lobe);
  });
  return bsdf_sample_make(vec3(r.wo_pdf), r.wo_pdf.w, vec3(r.value_eta), r.value_eta.w, r.lobe);
}

float GpuCoreCalls::bsdf_pdf(const Material& m, vec2 uv, vec3 wi, vec3 wo) {
  ProbeQuery q = make_query(PROBE_BSDF_PDF, material_index(m), vec4(uv, 0.0f, 0.0f), vec4(wi, 0.0f),
                            vec4(wo, 0.0f));
  return query(q, [&] { return pdf_result(cpu_core_calls().bsdf_pdf(m, uv, wi, wo)); }).wo_pdf.w;
}

vec3 GpuCoreCalls::bsdf_eval(const Material& m, vec2 uv, vec3 wi, vec3 wo) {
  ProbeQuery q = make_query(PROBE_BSDF_EVAL, material_index(m), vec4(uv, 0.0f, 0.0f),
                            vec4(wi, 0.0f), vec4(wo, 0.0f));
  return vec3(query(q, [&] {
                return make_result(vec3(0.0f), 0.0f, cpu_core_calls().bsdf_eval(m, uv, wi, wo),
                                   1.0f, 0u);
              }).value_eta);
}

void GpuCoreCalls::evaluate_misses() {
  auto start = std::chrono::steady_clock::now();
  ProbeScene scene{&materials_, &bsdf_suite::local_textures(), &bsdf_suite::local_texels()};
  std::vector<ProbeResult> results = device_.evaluate(misses_, scene);
  lockstep_.device_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  lockstep_.queries += misses_.size();
  ++lockstep_.batches;
  for (std::size_t i = 0; i < misses_.size(); ++i) {
    const ProbeQuery& q = misses_[i];
    const ProbeResult& gpu = results[i];
    const ProbeResult& cpu = predictions_[i];
    if (!finite(gpu)) {
      if (lockstep_.non_finite++ == 0) lockstep_.first_non_finite = describe(q);
    }
    auto note = [this](double& max, double d) {
      max = std::max(max, d);
      if (d > 1e-3) ++lockstep_.beyond_1e3;
    };
    bool sampled = q.op == PROBE_WARP_DIRECTION || q.op == PROBE_WARP_POINT ||
                   q.op == PROBE_MICROFACET_SAMPLE || q.op == PROBE_BSDF_SAMPLE;
    if (q.op == PROBE_BSDF_SAMPLE &&
        (gpu.lobe != cpu.lobe || (gpu.wo_pdf.w > 0.0f) != (cpu.wo_pdf.w > 0.0f))) {
      ++lockstep_.lobe_mismatch;
    } else if (sampled) {
      double d = 0.0;
      for (int c = 0; c < 3; ++c) d = std::max(d, double(std::abs(gpu.wo_pdf[c] - cpu.wo_pdf[c])));
      lockstep_.max_direction = std::max(lockstep_.max_direction, d);
    }
    if (q.op == PROBE_BSDF_SAMPLE && gpu.lobe == cpu.lobe) {
      note(lockstep_.max_pdf, relative(gpu.wo_pdf.w, cpu.wo_pdf.w));
      for (int c = 0; c < 3; ++c)
        note(lockstep_.max_value, relative(gpu.value_eta[c], cpu.value_eta[c]));
    } else if (q.op == PROBE_BSDF_EVAL) {
      for (int c = 0; c < 3; ++c)
        note(lockstep_.max_value, relative(gpu.value_eta[c], cpu.value_eta[c]));
    } else if (!sampled) {
      note(lockstep_.max_pdf, relative(gpu.wo_pdf.w, cpu.wo_pdf.w));
    }
  }
  const std::size_t first = queries_.size();
  if (first + misses_.size() >= kNone) throw std::runtime_error("too many queries in one check");
  queries_.insert(queries_.end(), misses_.begin(), misses_.end());
  results_.insert(results_.end(), results.begin(), results.end());
  if (queries_.size() * 2 > table_.size()) {
    std::size_t size = 1024;
    while (size < queries_.size() * 4) size *= 2;
    table_.assign(size, kNone);
    for (std::size_t p = 0; p < queries_.size(); ++p) insert(uint32_t(p));
  } else {
    for (std::size_t p = first; p < queries_.size(); ++p) insert(uint32_t(p));
  }
}

void GpuCoreCalls::run_check(const std::function<void()>& check) {
  auto forget = [this] {
    queries_.clear();
    results_.clear();
    table_.clear();
    tape_.clear();
    previous_tape_.clear();
    misses_.clear();
    predictions_.clear();
  };
  for (int pass = 1;; ++pass) {
    std::swap(tape_, previous_tape_);
    tape_.clear();
    misses_.clear();
    predictions_.clear();
    check();
    if (misses_.empty()) {
      // This run took every value from the device: its results stand.
      lockstep_.max_passes = std::max(lockstep_.max_passes, std::size_t(pass));
      forget();
      return;
    }
    if (pass == kMaxPasses) {
      std::size_t missed = misses_.size();
      forget();
      throw std::runtime_error("a check still asked for " + std::to_string(missed) +
                               " new values after " + std::to_string(kMaxPasses) + " runs");
    }
    evaluate_misses();
  }
}

Lockstep GpuCoreCalls::take_lockstep() {
  Lockstep l = lockstep_;
  lockstep_ = Lockstep();
  return l;
}

}  // namespace tr::bsdf_gpu
