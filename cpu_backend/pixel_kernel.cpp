// The CPU renderer's per-pixel routine as kernel TR_CPU_KERNEL of cpu_backend/cpu_kernels.h:
// this unit compiles the core with the feature guards of that kernel (cpu_backend/CMakeLists.txt
// compiles it once per kernel) and defines pixel_kernel_<TR_CPU_KERNEL>.
#define TR_FEATURE_VARIANT
#define TR_HAS_BSDF(type) ::tr::kernel_has(::tr::kKernel.bsdf_types, type)
#define TR_HAS_EMITTER(type) ::tr::kernel_has(::tr::kKernel.emitter_types, type)
#define TR_HAS_SHAPE(type) ::tr::kernel_has(::tr::kKernel.shape_types, type)
#define TR_HAS_TEXTURE(type) ::tr::kernel_has(::tr::kKernel.texture_types, type)
#define TR_HAS_MATERIAL_FLAG(flag) ((::tr::kKernel.material_flags & (flag)) != 0u)
#define TR_HAS_INTEGRATOR(type) ::tr::kernel_has(::tr::kKernel.integrator_types, type)
#define TR_HAS_AOV(type) ::tr::kernel_has(::tr::kKernel.aov_types, type)
#define TR_HAS_SAMPLER(type) ::tr::kernel_has(::tr::kKernel.sampler_types, type)
#define TR_HAS_TEXTURED_SLOT(k) ::tr::kernel_has(::tr::kKernel.textured_slots, k)
#define TR_HAS_EMITTER_SELECTION(s) ::tr::kernel_has(::tr::kKernel.emitter_selections, s)

#include "cpu_backend/cpu_kernels.h"

namespace tr {
constexpr SceneFeatures kKernel = kCpuKernels[TR_CPU_KERNEL].features;
constexpr bool kernel_has(std::uint32_t mask, std::uint32_t bit) {
  return (mask >> bit & 1u) != 0u;
}
}  // namespace tr

#include "core/integrator.h"
#include "core/integrators/aov.h"

#define TR_CONCAT_(a, b) a##b
#define TR_CONCAT(a, b) TR_CONCAT_(a, b)

namespace tr {

// With AOVs (core/integrators/aov.h) the camera ray is traced before the integrator runs, and
// its hit serves the integrator's first step.
void TR_CONCAT(pixel_kernel_, TR_CPU_KERNEL)(const EmbreeScene& accel, uvec2 pixel, size_t index,
                                             uint first, uint count, uint seed, FilmTarget& film,
                                             ThreadCounts& counts) {
  const Integrator it = scene_globals().integrator;
  const uint pass_size = film.pass_size;
  double negatives = film.negatives_before(index);
  for (uint i = first; i < first + count; ++i) {
    PathState s = integrator_begin(pixel, i, seed);
    const double positives = double(i) - negatives;
    bool camera_hit_pending = false;
    Hit camera_hit;
    if (it.aov_count > 0u) {
      camera_hit = accel.intersect(s.ray);
      ++counts.rays;
      camera_hit_pending = true;
      AovPoint a = aov_point(s.ray, camera_hit);
      for (uint k = 0; k < it.aov_count; ++k)
        film.add(film.aovs, index * it.aov_count + k, positives, integrator_negative(s),
                 aov_value(scene_aov_type(k), a));
    }
    while (integrator_alive(s)) {
      Hit hit = camera_hit_pending ? camera_hit : accel.intersect(s.ray);
      if (!camera_hit_pending) ++counts.rays;
      camera_hit_pending = false;
      ShadowRay sr = integrator_step(s, hit);
      if (sr.enabled != 0u) {
        ++counts.rays;
        if (!accel.occluded(sr.ray)) integrator_add_unoccluded(s, sr);
      }
    }
    vec3 L = integrator_result(s);
    if (!radiance_is_finite(L)) {
      ++counts.rejected;
      L = vec3(0.0f);
    }
    film.add(film.pixels, index, positives, integrator_negative(s), L);
    if (integrator_negative(s)) negatives += 1.0;
    if (pass_size > 0u && (i + 1u) % pass_size == 0u) {
      end_pass(film.pixels.passes(index));
      for (uint k = 0; k < it.aov_count; ++k) end_pass(film.aovs.passes(index * it.aov_count + k));
    }
  }
}

}  // namespace tr
