#include "gpu_core_calls.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <utility>

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

GpuCoreCalls::GpuCoreCalls(ProbeDevice& device)
    : memo_(
          [&device](const ProbeQuery* queries, std::size_t count, ProbeResult* results) {
            ProbeScene scene{&bsdf_suite::local_materials(), &bsdf_suite::local_textures(),
                             &bsdf_suite::local_texels()};
            device.evaluate(queries, count, scene, results);
          },
          device_batch::EvaluatorPolicy{"bsdf_gpu", kSpeculativeRuns},
          [this](const ProbeQuery* queries, const ProbeResult* gpu, const ProbeResult* cpu,
                 std::size_t count) { compare(queries, gpu, cpu, count); }) {}

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
  return vec3(memo_
                  .lookup(q,
                          [&] {
                            return make_result(cpu_core_calls().warp_direction(w, parameter, u),
                                               0.0f, vec3(0.0f), 1.0f, 0u);
                          })
                  .wo_pdf);
}

float GpuCoreCalls::warp_direction_pdf(Warp w, float parameter, vec3 d) {
  ProbeQuery q = make_query(PROBE_WARP_DIRECTION_PDF, uint(w), vec4(d, parameter));
  return memo_
      .lookup(q, [&] { return pdf_result(cpu_core_calls().warp_direction_pdf(w, parameter, d)); })
      .wo_pdf.w;
}

vec2 GpuCoreCalls::warp_point(Warp w, vec2 u) {
  ProbeQuery q = make_query(PROBE_WARP_POINT, uint(w), vec4(u, 0.0f, 0.0f));
  return vec2(memo_
                  .lookup(q,
                          [&] {
                            return make_result(vec3(cpu_core_calls().warp_point(w, u), 0.0f), 0.0f,
                                               vec3(0.0f), 1.0f, 0u);
                          })
                  .wo_pdf);
}

float GpuCoreCalls::warp_point_pdf(Warp w, vec2 p) {
  ProbeQuery q = make_query(PROBE_WARP_POINT_PDF, uint(w), vec4(p, 0.0f, 0.0f));
  return memo_.lookup(q, [&] { return pdf_result(cpu_core_calls().warp_point_pdf(w, p)); })
      .wo_pdf.w;
}

vec3 GpuCoreCalls::microfacet_sample(Microfacet d, vec3 wi, vec2 u) {
  ProbeQuery q =
      make_query(PROBE_MICROFACET_SAMPLE, microfacet_flags(d),
                 vec4(d.alpha_u, d.alpha_v, 0.0f, 0.0f), vec4(wi, 0.0f), vec4(u, 0.0f, 0.0f));
  return vec3(memo_
                  .lookup(q,
                          [&] {
                            return make_result(cpu_core_calls().microfacet_sample(d, wi, u), 0.0f,
                                               vec3(0.0f), 1.0f, 0u);
                          })
                  .wo_pdf);
}

float GpuCoreCalls::microfacet_pdf(Microfacet d, vec3 wi, vec3 m) {
  ProbeQuery q = make_query(PROBE_MICROFACET_PDF, microfacet_flags(d),
                            vec4(d.alpha_u, d.alpha_v, 0.0f, 0.0f), vec4(wi, 0.0f), vec4(m, 0.0f));
  return memo_.lookup(q, [&] { return pdf_result(cpu_core_calls().microfacet_pdf(d, wi, m)); })
      .wo_pdf.w;
}

BsdfSample GpuCoreCalls::bsdf_sample(const Material& m, vec2 uv, vec3 wi, float u1, vec2 u2) {
  ProbeQuery q = make_query(PROBE_BSDF_SAMPLE, material_index(m), vec4(uv, u1, 0.0f),
                            vec4(wi, 0.0f), vec4(u2, 0.0f, 0.0f));
  ProbeResult r = memo_.lookup(q, [&] {
    BsdfSample s = cpu_core_calls().bsdf_sample(m, uv, wi, u1, u2);
    return make_result(s.wo, s.pdf, s.weight, s.eta, s.lobe);
  });
  return bsdf_sample_make(vec3(r.wo_pdf), r.wo_pdf.w, vec3(r.value_eta), r.value_eta.w, r.lobe);
}

float GpuCoreCalls::bsdf_pdf(const Material& m, vec2 uv, vec3 wi, vec3 wo) {
  ProbeQuery q = make_query(PROBE_BSDF_PDF, material_index(m), vec4(uv, 0.0f, 0.0f), vec4(wi, 0.0f),
                            vec4(wo, 0.0f));
  return memo_.lookup(q, [&] { return pdf_result(cpu_core_calls().bsdf_pdf(m, uv, wi, wo)); })
      .wo_pdf.w;
}

vec3 GpuCoreCalls::bsdf_eval(const Material& m, vec2 uv, vec3 wi, vec3 wo) {
  ProbeQuery q = make_query(PROBE_BSDF_EVAL, material_index(m), vec4(uv, 0.0f, 0.0f),
                            vec4(wi, 0.0f), vec4(wo, 0.0f));
  return vec3(memo_
                  .lookup(q,
                          [&] {
                            return make_result(vec3(0.0f), 0.0f,
                                               cpu_core_calls().bsdf_eval(m, uv, wi, wo), 1.0f, 0u);
                          })
                  .value_eta);
}

void GpuCoreCalls::compare(const ProbeQuery* queries, const ProbeResult* gpu_results,
                           const ProbeResult* cpu_results, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    const ProbeQuery& q = queries[i];
    const ProbeResult& gpu = gpu_results[i];
    const ProbeResult& cpu = cpu_results[i];
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
}

Lockstep GpuCoreCalls::take_lockstep() {
  Lockstep l = std::exchange(lockstep_, Lockstep());
  const device_batch::EvaluatorStats stats = memo_.take_stats();
  l.queries = stats.evaluations;
  l.batches = stats.batches;
  l.max_runs = stats.max_runs;
  l.immediate = stats.immediate;
  l.device_seconds = stats.device_seconds;
  return l;
}

}  // namespace tr::bsdf_gpu
