#include "gpu_core_calls.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
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
  if (o.max_pdf > max_pdf) worst_pdf = o.worst_pdf;
  if (o.max_value > max_value) worst_value = o.worst_value;
  if (non_finite == 0 && o.non_finite > 0) first_non_finite = o.first_non_finite;
  queries += o.queries;
  batches += o.batches;
  max_runs = std::max(max_runs, o.max_runs);
  immediate += o.immediate;
  lobe_mismatch += o.lobe_mismatch;
  max_direction = std::max(max_direction, o.max_direction);
  max_pdf = std::max(max_pdf, o.max_pdf);
  max_value = std::max(max_value, o.max_value);
  beyond_1e3 += o.beyond_1e3;
  non_finite += o.non_finite;
  device_seconds += o.device_seconds;
}

std::string Lockstep::differences() const {
  std::ostringstream s;
  s << std::setprecision(3) << "dir " << max_direction << "  pdf " << max_pdf << "  value "
    << max_value << "  >1e-3: " << beyond_1e3 << "/" << queries << "  other lobe: " << lobe_mismatch
    << "  NaN/Inf: " << non_finite;
  return s.str();
}

std::string Lockstep::summary() const {
  std::ostringstream s;
  s << queries << " device evaluations in " << batches << " batches (" << immediate
    << " one by one; " << device_seconds << " s on the device; at most " << max_runs
    << " runs per check); GPU vs C++ at the same "
    << "arguments: max |d direction| " << max_direction << ", max rel d pdf " << max_pdf
    << ", max rel d weight/eval " << max_value << ", " << beyond_1e3
    << " values off by > 1e-3 relative, " << lobe_mismatch << " samples of another lobe, "
    << non_finite << " NaN/Inf";
  if (non_finite > 0) s << " (first: " << first_non_finite << ")";
  if (max_pdf > 0.0) s << "\n  largest pdf difference: " << worst_pdf;
  if (max_value > 0.0) s << "\n  largest weight/eval difference: " << worst_value;
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

// A table slot holds (upper 32 bits of the query's hash) << 32 | position; the tag spares most
// probes a look at the query itself.
uint32_t GpuCoreCalls::find(const ProbeQuery& q) const {
  if (table_.empty()) return kNone;
  const std::size_t mask = table_.size() - 1;
  const uint64_t h = hash_of(q);
  const uint32_t tag = uint32_t(h >> 32);
  for (std::size_t slot = h & mask;; slot = (slot + 1) & mask) {
    uint64_t e = table_[slot];
    if (e == kEmptySlot) return kNone;
    uint32_t p = uint32_t(e);
    if (uint32_t(e >> 32) == tag && same(queries_[p], q)) return p;
  }
}

void GpuCoreCalls::index(std::size_t first, std::size_t last) {
  // Hashes first, then inserts with the slot of a later query prefetched: the table is far
  // larger than the caches.
  constexpr std::size_t kAhead = 16;
  std::vector<uint64_t> hashes(last - first);
  for (std::size_t p = first; p < last; ++p) hashes[p - first] = hash_of(queries_[p]);
  const std::size_t mask = table_.size() - 1;
  for (std::size_t i = 0; i < hashes.size(); ++i) {
    if (i + kAhead < hashes.size()) __builtin_prefetch(&table_[hashes[i + kAhead] & mask], 1);
    const uint32_t position = uint32_t(first + i);
    const uint32_t tag = uint32_t(hashes[i] >> 32);
    for (std::size_t slot = hashes[i] & mask;; slot = (slot + 1) & mask) {
      uint64_t& e = table_[slot];
      if (e == kEmptySlot) {
        e = uint64_t(tag) << 32 | position;
        break;
      }
      // A duplicate keeps the first.
      if (uint32_t(e >> 32) == tag && same(queries_[uint32_t(e)], queries_[position])) break;
    }
  }
}

template <typename Cpu>
ProbeResult GpuCoreCalls::query(const ProbeQuery& q, Cpu cpu) {
  if (cursor_ < previous_tape_.size()) {
    uint32_t p = previous_tape_[cursor_];
    if (p < queries_.size() && same(queries_[p], q)) {
      ++cursor_;
      tape_.push_back(p);
      return results_[p];
    }
  }
  uint32_t p = find(q);
  if (p != kNone) {
    // Calls were added or dropped since the previous run: continue its tape after this call.
    if (tape_index_[p] != kNone) cursor_ = tape_index_[p] + 1;
    tape_.push_back(p);
    return results_[p];
  }
  // After evaluate_misses() this query sits at queries_.size() + its index among the misses.
  tape_.push_back(uint32_t(queries_.size() + misses_.size()));
  misses_.push_back(q);
  predictions_.push_back(cpu());
  if (!immediate_) return predictions_.back();
  ++lockstep_.immediate;
  evaluate_misses();
  return results_.back();
}

uint GpuCoreCalls::material_index(const Material& m) {
  // A check asks about one material at a time.
  const std::vector<Material>& materials = bsdf_suite::local_materials();
  if (last_material_ < materials.size() &&
      std::memcmp(&materials[last_material_], &m, sizeof(Material)) == 0)
    return last_material_;
  std::string bytes(reinterpret_cast<const char*>(&m), sizeof(Material));
  auto it = material_indices_.find(bytes);
  if (it == material_indices_.end()) {
    it = material_indices_.emplace(bytes, bsdf_suite::add_material(m)).first;
  }
  last_material_ = it->second;
  return last_material_;
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
  ProbeScene scene{&bsdf_suite::local_materials(), &bsdf_suite::local_textures(),
                   &bsdf_suite::local_texels()};
  const std::size_t first = queries_.size();
  if (first + misses_.size() >= kNone) throw std::runtime_error("too many queries in one check");
  results_.resize(first + misses_.size());
  device_.evaluate(misses_, scene, results_.data() + first);
  const ProbeResult* results = results_.data() + first;
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
    auto note = [&](double& max, std::string& worst, float g, float c) {
      double d = relative(g, c);
      if (d > 1e-3) ++lockstep_.beyond_1e3;
      if (d > max) {
        max = d;
        std::ostringstream s;
        s << std::setprecision(9) << describe(q) << ": GPU " << g << ", C++ " << c;
        worst = s.str();
      }
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
    Lockstep& l = lockstep_;
    if ((q.op == PROBE_BSDF_SAMPLE && gpu.lobe == cpu.lobe) ||
        (!sampled && q.op != PROBE_BSDF_EVAL))
      note(l.max_pdf, l.worst_pdf, gpu.wo_pdf.w, cpu.wo_pdf.w);
    if ((q.op == PROBE_BSDF_SAMPLE && gpu.lobe == cpu.lobe) || q.op == PROBE_BSDF_EVAL) {
      for (int c = 0; c < 3; ++c)
        note(l.max_value, l.worst_value, gpu.value_eta[c], cpu.value_eta[c]);
    }
  }
  queries_.insert(queries_.end(), misses_.begin(), misses_.end());
  misses_.clear();
  predictions_.clear();
  if (queries_.size() * 2 > table_.size()) {
    std::size_t size = 1024;
    while (size < queries_.size() * 4) size *= 2;
    table_.assign(size, kEmptySlot);
    index(0, queries_.size());
  } else {
    index(first, queries_.size());
  }
}

void GpuCoreCalls::run_check(const std::function<void()>& check) {
  auto forget = [this] {
    queries_.clear();
    results_.clear();
    table_.clear();
    tape_.clear();
    previous_tape_.clear();
    tape_index_.clear();
  };
  for (int run = 1;; ++run) {
    std::swap(tape_, previous_tape_);
    tape_.clear();
    cursor_ = 0;
    tape_index_.assign(queries_.size(), kNone);
    for (std::size_t i = previous_tape_.size(); i-- > 0;)
      tape_index_[previous_tape_[i]] = uint32_t(i);
    immediate_ = run > kSpeculativeRuns;
    try {
      check();
    } catch (...) {
      forget();
      throw;
    }
    if (misses_.empty()) {
      // This run took every value from the device: its results stand.
      lockstep_.max_runs = std::max(lockstep_.max_runs, std::size_t(run));
      forget();
      return;
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
