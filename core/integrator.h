// The integrator interface every backend drives, identical on CPU and GPU:
//
//   PathState s = integrator_begin(pixel, sample_index, seed);
//   while (integrator_alive(s)) {
//     Hit hit = <closest hit of s.ray, or miss_hit()>;
//     ShadowRay sr = integrator_step(s, hit);
//     if (sr.enabled != 0u && <sr.ray unoccluded>) integrator_add_unoccluded(s, sr);
//   }
//   vec3 L = integrator_result(s);   // reject (count, score 0) if !radiance_is_finite(L)
//
// Random numbers come from the counter-based RNG keyed by (seed, pixel, sample index), so a
// sample's value does not depend on which thread, tile or dispatch computes it.
#ifndef TWINRAY_CORE_INTEGRATOR_H
#define TWINRAY_CORE_INTEGRATOR_H

#include "core/camera.h"
#include "core/integrators/direct.h"
#include "core/integrators/path.h"

TR_NAMESPACE_BEGIN

INLINE PathState integrator_begin(uvec2 pixel, uint sample_index, uint seed) {
  SceneGlobals g = scene_globals();
  Camera c = g.camera;
  PathState s;
  s.rng = rng_init(pixel.y * c.width + pixel.x, sample_index, seed);
  vec2 film = sample_film_position(c, pixel, rng_next_2d(s.rng), s.filter_weight);
  s.ray = camera_ray(c, film, rng_next_2d(s.rng));
  s.throughput = vec3(1.0f);
  s.eta = 1.0f;
  s.radiance = vec3(0.0f);
  s.prev_bsdf_pdf = 1.0f;
  s.prev_p = s.ray.o;
  s.prev_bsdf_delta = 1u;
  s.depth = 0u;
  s.alive = (g.integrator.type == INTEGRATOR_PATH && g.integrator.max_depth == 0) ? 0u : 1u;
  s.stage = 0u;
  s.anchor_frame = frame_from_normal(vec3(0.0f, 0.0f, 1.0f));
  s.anchor_p = vec3(0.0f);
  s.anchor_material = 0u;
  s.anchor_ng = vec3(0.0f, 0.0f, 1.0f);
  s.anchor_smooth = 0u;
  s.anchor_wi = vec3(0.0f, 0.0f, 1.0f);
  s.pad0 = 0.0f;
  s.anchor_uv = vec2(0.0f);
  return s;
}

INLINE bool integrator_alive(PathState s) { return s.alive != 0u; }

INLINE ShadowRay integrator_step(INOUT(PathState) s, Hit hit) {
  Integrator it = scene_globals().integrator;
  if (TR_HAS_INTEGRATOR(INTEGRATOR_DIRECT) && it.type == INTEGRATOR_DIRECT) return direct_step(s, hit, it);
  if (TR_HAS_INTEGRATOR(INTEGRATOR_PATH) && it.type == INTEGRATOR_PATH) return path_step(s, hit, it);
  s.alive = 0u;
  return no_shadow_ray();
}

INLINE void integrator_add_unoccluded(INOUT(PathState) s, ShadowRay sr) { s.radiance += sr.contribution; }

INLINE vec3 integrator_result(PathState s) { return s.radiance * s.filter_weight; }

INLINE bool radiance_is_finite(vec3 L) { return !any(isnan(L)) && !any(isinf(L)); }

TR_NAMESPACE_END

#endif
