// Mitsuba 3's `path` integrator, one vertex per call: unidirectional path tracing with
// emitter sampling and BSDF sampling combined by multiple importance sampling (power
// heuristic, Veach 1997 §9.2), Russian roulette from `rr_depth` on, and `max_depth` /
// `hide_emitters` with Mitsuba's meaning (src/integrators/path.cpp): max_depth counts
// scattering events plus one (1: emitters seen directly only, 2: direct illumination,
// -1: unbounded); hidden emitters are skipped by camera rays.
#ifndef TWINRAY_CORE_INTEGRATORS_PATH_H
#define TWINRAY_CORE_INTEGRATORS_PATH_H

#include "core/bsdf.h"
#include "core/emitter.h"
#include "core/integrators/path_state.h"
#include "core/interaction.h"
#include "core/mis.h"

TR_NAMESPACE_BEGIN

// Russian roulette with Mitsuba's survival probability min(max(throughput) eta^2, 0.95)
// (pbrt-v4 §14.1.4 for the estimator: survivors are divided by the probability).
INLINE bool russian_roulette_survives(INOUT(PathState) s, Integrator it) {
  float throughput_max = max_component(s.throughput);
  if (int(s.depth) >= it.rr_depth) {
    float q = min(throughput_max * s.eta * s.eta, 0.95f);
    if (!(rng_next_1d(s.rng) < q)) return false;
    s.throughput /= q;
  }
  return throughput_max != 0.0f;
}

INLINE ShadowRay path_step(INOUT(PathState) s, Hit hit, Integrator it) {
  ShadowRay sr = no_shadow_ray();
  bool hidden = s.depth == 0u && it.hide_emitters != 0u;
  if (hit.shape == NO_INDEX) {
    vec3 le = eval_environment(s.ray.d);
    if (!hidden && any(notEqual(le, vec3(0.0f)))) {
      float em_pdf = s.prev_bsdf_delta != 0u ? 0.0f : pdf_environment(s.ray.d);
      s.radiance += s.throughput * le * power_heuristic(s.prev_bsdf_pdf, em_pdf);
    }
    s.alive = 0u;
    return sr;
  }
  SurfaceInteraction si = surface_interaction(s.ray, hit);
  if (si.emitter != NO_INDEX) {
    if (hidden) {
      s.ray = spawn_ray(si.p, si.ng, s.ray.d);
      return sr;
    }
    float em_pdf = s.prev_bsdf_delta != 0u ? 0.0f : pdf_emitter_surface(s.prev_p, si);
    s.radiance += s.throughput * eval_emitter_surface(si) * power_heuristic(s.prev_bsdf_pdf, em_pdf);
  }
  if (!(it.max_depth < 0 || int(s.depth) + 1 < it.max_depth)) {
    s.alive = 0u;
    return sr;
  }
  Material m = scene_material(si.material);
  if ((bsdf_flags(m, si.uv) & BSDF_SMOOTH) != 0u) {
    EmitterSample es = sample_emitter(si.p, s.rng);
    if (es.pdf > 0.0f) {
      vec3 wo = frame_to_local(si.frame, es.d);
      vec3 f = bsdf_eval(m, si.uv, si.wi, wo);
      float mis = es.delta != 0u ? 1.0f : power_heuristic(es.pdf, bsdf_pdf(m, si.uv, si.wi, wo));
      sr.contribution = s.throughput * f * es.weight * mis;
      if (any(notEqual(sr.contribution, vec3(0.0f)))) {
        sr.enabled = 1u;
        sr.ray = shadow_ray_to(si.p, si.ng, es.p, es.n, es.d, es.dist);
      }
    }
  }
  float u1 = rng_next_1d(s.rng);
  BsdfSample bs = bsdf_sample(m, si.uv, si.wi, u1, rng_next_2d(s.rng));
  s.ray = spawn_ray(si.p, si.ng, frame_to_world(si.frame, bs.wo));
  s.throughput *= bs.weight;
  s.eta *= bs.eta;
  s.prev_p = si.p;
  s.prev_bsdf_pdf = bs.pdf;
  s.prev_bsdf_delta = (bs.lobe & BSDF_DELTA) != 0u ? 1u : 0u;
  s.depth += 1u;
  bool survives = russian_roulette_survives(s, it);
  s.alive = (survives && bs.pdf > 0.0f) ? 1u : 0u;
  return sr;
}

TR_NAMESPACE_END

#endif
