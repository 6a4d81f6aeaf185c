#include "core_calls.h"

#include <stdexcept>

#include "core/bsdf.h"
#include "core/warp.h"

namespace tr::bsdf_suite {
namespace {

class CpuCoreCalls : public CoreCalls {
 public:
  vec3 warp_direction(Warp w, float parameter, vec2 u) override {
    switch (w) {
      case Warp::cosine_hemisphere:
        return square_to_cosine_hemisphere(u);
      case Warp::uniform_sphere:
        return square_to_uniform_sphere(u);
      case Warp::uniform_hemisphere:
        return square_to_uniform_hemisphere(u);
      case Warp::uniform_cone:
        return square_to_uniform_cone(u, parameter);
      default:
        throw std::logic_error("not a direction warp");
    }
  }
  float warp_direction_pdf(Warp w, float parameter, vec3 d) override {
    switch (w) {
      case Warp::cosine_hemisphere:
        return square_to_cosine_hemisphere_pdf(d);
      case Warp::uniform_sphere:
        return square_to_uniform_sphere_pdf(d);
      case Warp::uniform_hemisphere:
        return square_to_uniform_hemisphere_pdf(d);
      case Warp::uniform_cone:
        return square_to_uniform_cone_pdf(d, parameter);
      default:
        throw std::logic_error("not a direction warp");
    }
  }
  vec2 warp_point(Warp w, vec2 u) override {
    switch (w) {
      case Warp::disk_concentric:
        return square_to_uniform_disk_concentric(u);
      case Warp::triangle:
        return square_to_uniform_triangle(u);
      default:
        throw std::logic_error("not a planar warp");
    }
  }
  float warp_point_pdf(Warp w, vec2 p) override {
    if (w != Warp::disk_concentric) throw std::logic_error("no density in core/warp.h");
    return square_to_uniform_disk_concentric_pdf(p);
  }
  vec3 microfacet_sample(Microfacet d, vec3 wi, vec2 u) override {
    return tr::microfacet_sample(d, wi, u);
  }
  float microfacet_pdf(Microfacet d, vec3 wi, vec3 m) override {
    return tr::microfacet_pdf(d, wi, m);
  }
  BsdfSample bsdf_sample(const Material& m, vec2 uv, vec3 wi, float u1, vec2 u2) override {
    return tr::bsdf_sample(m, uv, wi, u1, u2);
  }
  float bsdf_pdf(const Material& m, vec2 uv, vec3 wi, vec3 wo) override {
    return tr::bsdf_pdf(m, uv, wi, wo);
  }
  vec3 bsdf_eval(const Material& m, vec2 uv, vec3 wi, vec3 wo) override {
    return tr::bsdf_eval(m, uv, wi, wo);
  }
};

}  // namespace

CoreCalls& cpu_core_calls() {
  static CpuCoreCalls calls;
  return calls;
}

}  // namespace tr::bsdf_suite
