// The core/ entry points the suite's cases exercise, behind one interface so the same cases
// validate both builds of core/: the C++ one (cpu_core_calls) and the GLSL one, evaluated by a
// compute shader (tests/bsdf_gpu).
#ifndef TWINRAY_TESTS_BSDF_CORE_CALLS_H
#define TWINRAY_TESTS_BSDF_CORE_CALLS_H

#include <functional>

#include "core/bsdf/common.h"
#include "core/microfacet.h"
#include "core/scene_types.h"

namespace tr::bsdf_suite {

// The warps of core/warp.h. Direction warps return unit vectors; the planar ones points.
enum class Warp : uint {
  cosine_hemisphere,
  uniform_sphere,
  uniform_hemisphere,
  uniform_cone,  // parameter: cos_max
  disk_concentric,
  triangle,  // barycentrics (b1, b2); no density of its own
};

class CoreCalls {
 public:
  virtual ~CoreCalls() = default;

  virtual vec3 warp_direction(Warp w, float parameter, vec2 u) = 0;
  virtual float warp_direction_pdf(Warp w, float parameter, vec3 d) = 0;
  virtual vec2 warp_point(Warp w, vec2 u) = 0;
  virtual float warp_point_pdf(Warp w, vec2 p) = 0;

  virtual vec3 microfacet_sample(Microfacet d, vec3 wi, vec2 u) = 0;
  virtual float microfacet_pdf(Microfacet d, vec3 wi, vec3 m) = 0;

  virtual BsdfSample bsdf_sample(const Material& m, vec2 uv, vec3 wi, float u1, vec2 u2) = 0;
  virtual float bsdf_pdf(const Material& m, vec2 uv, vec3 wi, vec3 wo) = 0;
  virtual vec3 bsdf_eval(const Material& m, vec2 uv, vec3 wi, vec3 wo) = 0;

  // Runs one check of twinray::validation (twinray::validation::CheckRunner): once here; a
  // batching implementation repeats it until every value came from its batch.
  virtual void run_check(const std::function<void()>& check) { check(); }
};

// core/ compiled as C++.
CoreCalls& cpu_core_calls();

}  // namespace tr::bsdf_suite

#endif
