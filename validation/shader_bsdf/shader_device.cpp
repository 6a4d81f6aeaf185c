#include "shader_device.h"

#include <cstring>

namespace tr::shader_bsdf {

namespace {

// Runs of one check answered provisionally (zeros); a later run evaluates each miss on the device
// at once, so it completes: the chi-square's adaptive quadrature of a near-mirror lobe keeps
// refining run after run. A check still asking after kMaxRuns is an error (it cannot be).
constexpr int kSpeculativeRuns = 16;
constexpr int kMaxRuns = 64;

static_assert(sizeof(ShaderDevice::Query) == 48 && sizeof(ShaderDevice::Result) == 32,
              "std430 layout of the wrapper's Query and Result");

// The wrapper's bindings and workgroup (shader_source.cpp): set 0 holds the queries, the results
// and the parameters.
constexpr device_batch::Binding kQueries{0, 0}, kResults{0, 1}, kParameters{0, 2};
constexpr uint32_t kWorkgroup = 64;

ShaderDevice::Query make_query(uint32_t op, const glm::vec3& wi, const glm::vec3& arg) {
  ShaderDevice::Query q;
  std::memset(&q, 0, sizeof(q));
  q.op = op;
  q.wi[0] = wi.x;
  q.wi[1] = wi.y;
  q.wi[2] = wi.z;
  q.arg[0] = arg.x;
  q.arg[1] = arg.y;
  q.arg[2] = arg.z;
  return q;
}

}  // namespace

ShaderDevice::ShaderDevice(const std::vector<uint32_t>& spirv, const std::string& selector)
    : kernel_(
          spirv.data(), spirv.size() * sizeof(uint32_t),
          device_batch::KernelLayout{{{kQueries.binding, kResults.binding, kParameters.binding}},
                                     kQueries,
                                     kResults,
                                     kWorkgroup},
          selector, "check-bsdf wrapper") {
  kernel_.build();
}

void ShaderDevice::evaluate(const Query* queries, std::size_t count,
                            const std::vector<float>& parameters, Result* results) {
  kernel_.fill(kParameters, parameters);
  kernel_.evaluate(queries, count, results);
}

ShaderBsdf::ShaderBsdf(ShaderDevice& device, std::vector<float> parameters)
    : parameters_(std::move(parameters)),
      memo_(
          [&device, this](const ShaderDevice::Query* queries, std::size_t count,
                          ShaderDevice::Result* results) {
            device.evaluate(queries, count, parameters_, results);
          },
          device_batch::EvaluatorPolicy{"check-bsdf", kSpeculativeRuns, kMaxRuns}) {}

validation::BsdfUnderTest ShaderBsdf::under_test(const std::string& name, bool reciprocal) {
  auto* memo = &memo_;
  validation::BsdfUnderTest b;
  b.name = name;
  b.eval_includes_cosine = true;
  b.reciprocal = reciprocal;
  b.sample = [memo](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    const ShaderDevice::Result r = memo->lookup(make_query(0, wi, glm::vec3(u1, u2.x, u2.y)));
    validation::BsdfSample s;
    s.wo = glm::vec3(r.wo_pdf[0], r.wo_pdf[1], r.wo_pdf[2]);
    s.pdf = r.wo_pdf[3];
    s.weight = glm::vec3(r.value[0], r.value[1], r.value[2]);
    return s;
  };
  b.pdf = [memo](const glm::vec3& wi, const glm::vec3& wo) {
    return memo->lookup(make_query(1, wi, wo)).wo_pdf[3];
  };
  b.eval = [memo](const glm::vec3& wi, const glm::vec3& wo) {
    const ShaderDevice::Result r = memo->lookup(make_query(2, wi, wo));
    return glm::vec3(r.value[0], r.value[1], r.value[2]);
  };
  return b;
}

}  // namespace tr::shader_bsdf
