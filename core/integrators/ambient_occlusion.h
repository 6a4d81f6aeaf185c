// pbrt-v4's `ambientocclusion` integrator (src/pbrt/cpu/integrators.cpp, AOIntegrator::Li;
// Mitsuba 3 has none): at the camera ray's first hit, one direction wi of the hemisphere
// around the geometric normal n turned towards the ray (pbrt-v4: FaceForward(isect.n, -ray.d),
// the true geometry, not the shading normal), drawn cosine-weighted (`cossample`, pdf
// cos(theta) / pi, pbrt-v4 §A.5.3) or uniformly (pdf 1 / (2 pi), §A.5.2), scores
//   V(wi, max_distance) cos(theta) / (pi pdf),
// an unbiased estimate of (1 / pi) ∫_H V(w, max_distance) cos(theta) dw, which is in [0, 1] and
// 1 where nothing lies within max_distance. pbrt-v4 multiplies it by the film's illuminant
// spectrum; twinray's film is RGB, whose white is (1, 1, 1). A camera ray that misses scores 0
// (pbrt-v4 returns L = 0). pbrt-v4 skips surfaces without a BSDF; twinray has none.
//
// One integrator_step: the camera ray's hit yields the occlusion ray as the ShadowRay, its
// tmax = max_distance, its contribution the score above; the sample then ends.
#ifndef TWINRAY_CORE_INTEGRATORS_AMBIENT_OCCLUSION_H
#define TWINRAY_CORE_INTEGRATORS_AMBIENT_OCCLUSION_H

#include "core/frame.h"
#include "core/integrators/path_state.h"
#include "core/interaction.h"
#include "core/scene_types.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

INLINE ShadowRay ambient_occlusion_step(INOUT(PathState) s, IN(Hit) hit, IN(Integrator) it) {
  s.alive = 0u;
  if (hit.shape == NO_INDEX) return no_shadow_ray();
  SurfaceInteraction si = surface_interaction(s.ray, hit);
  vec3 n = dot(si.ng, s.ray.d) > 0.0f ? -si.ng : si.ng;
  vec2 u = rng_next_2d(s.rng);
  vec3 wi = it.cos_sample != 0u ? square_to_cosine_hemisphere(u) : square_to_uniform_hemisphere(u);
  float pdf = it.cos_sample != 0u ? square_to_cosine_hemisphere_pdf(wi)
                                  : square_to_uniform_hemisphere_pdf(wi);
  if (!(pdf > 0.0f)) return no_shadow_ray();
  ShadowRay sr;
  sr.ray = spawn_ray(si.p, n, frame_to_world(frame_from_normal(n), wi));
  sr.ray.tmax = it.max_distance;
  sr.contribution = vec3(cos_theta(wi) / (PI * pdf));
  sr.enabled = 1u;
  return sr;
}

TR_NAMESPACE_END

#endif
