// Mitsuba 3's `direct` integrator (src/integrators/direct.cpp): at the first surface hit,
// `emitter_samples` emitter samples and `bsdf_samples` BSDF samples, combined by the power
// heuristic with sample counts (Veach 1997, eq. 9.13 with n_i p_i). Emitters seen by the
// camera ray count in full unless `hide_emitters`.
//
// One sampling round per call: round k traces the emitter sample k's shadow ray (k <
// emitter_samples) and the BSDF sample k's ray (k < bsdf_samples), whose hit the next call
// scores. Rounds past the last BSDF sample trace an empty ray (tmax = 0) that hits nothing.
// Unlike Mitsuba, delta emitter samples are averaged over `emitter_samples` like the others
// (Mitsuba weights each of them 1, which over-counts point and directional lights when
// emitter_samples > 1).
#ifndef TWINRAY_CORE_INTEGRATORS_DIRECT_H
#define TWINRAY_CORE_INTEGRATORS_DIRECT_H

#include "core/bsdf.h"
#include "core/emitter.h"
#include "core/integrators/path_state.h"
#include "core/interaction.h"
#include "core/mis.h"

TR_NAMESPACE_BEGIN

INLINE void direct_score_bsdf_hit(INOUT(PathState) s, Hit hit, Integrator it) {
  float frac_bsdf = float(it.bsdf_samples) / float(it.bsdf_samples + it.emitter_samples);
  float frac_lum = 1.0f - frac_bsdf;
  vec3 le;
  float em_pdf;
  if (hit.shape == NO_INDEX) {
    le = eval_environment(s.ray.d);
    em_pdf = pdf_environment(s.ray.d);
  } else {
    SurfaceInteraction si = surface_interaction(s.ray, hit);
    if (si.emitter == NO_INDEX) return;
    le = eval_emitter_surface(si);
    em_pdf = pdf_emitter_surface(s.anchor_p, si);
  }
  if (s.prev_bsdf_delta != 0u) em_pdf = 0.0f;
  float mis = power_heuristic(s.prev_bsdf_pdf * frac_bsdf, em_pdf * frac_lum);
  s.radiance += s.throughput * le * mis / float(it.bsdf_samples);
}

INLINE ShadowRay direct_round(INOUT(PathState) s, uint k, Integrator it) {
  ShadowRay sr = no_shadow_ray();
  Material m = scene_material(s.anchor_material);
  float frac_bsdf = float(it.bsdf_samples) / float(it.bsdf_samples + it.emitter_samples);
  float frac_lum = 1.0f - frac_bsdf;
  if (k < it.emitter_samples && s.anchor_smooth != 0u) {
    EmitterSample es = sample_emitter(s.anchor_p, s.rng);
    if (es.pdf > 0.0f) {
      vec3 wo = frame_to_local(s.anchor_frame, es.d);
      vec3 f = bsdf_eval(m, s.anchor_uv, s.anchor_wi, wo);
      float mis = es.delta != 0u ? 1.0f
                                 : power_heuristic(es.pdf * frac_lum,
                                                   bsdf_pdf(m, s.anchor_uv, s.anchor_wi, wo) * frac_bsdf);
      sr.contribution = f * es.weight * mis / float(it.emitter_samples);
      if (any(notEqual(sr.contribution, vec3(0.0f)))) {
        sr.enabled = 1u;
        sr.ray = shadow_ray_to(s.anchor_p, s.anchor_ng, es.p, es.n, es.d, es.dist);
      }
    }
  }
  s.throughput = vec3(0.0f);
  s.ray = make_ray(s.anchor_p, s.anchor_frame.n, 0.0f);
  if (k < it.bsdf_samples) {
    float u1 = rng_next_1d(s.rng);
    BsdfSample bs = bsdf_sample(m, s.anchor_uv, s.anchor_wi, u1, rng_next_2d(s.rng));
    if (bs.pdf > 0.0f && any(notEqual(bs.weight, vec3(0.0f)))) {
      s.ray = spawn_ray(s.anchor_p, s.anchor_ng, frame_to_world(s.anchor_frame, bs.wo));
      s.throughput = bs.weight;
      s.prev_bsdf_pdf = bs.pdf;
      s.prev_bsdf_delta = (bs.lobe & BSDF_DELTA) != 0u ? 1u : 0u;
    }
  }
  return sr;
}

INLINE ShadowRay direct_step(INOUT(PathState) s, Hit hit, Integrator it) {
  uint rounds = max(it.emitter_samples, it.bsdf_samples);
  if (s.stage == 0u) {
    if (hit.shape == NO_INDEX) {
      if (it.hide_emitters == 0u) s.radiance += eval_environment(s.ray.d);
      s.alive = 0u;
      return no_shadow_ray();
    }
    SurfaceInteraction si = surface_interaction(s.ray, hit);
    if (si.emitter != NO_INDEX) {
      if (it.hide_emitters != 0u) {
        s.ray = spawn_ray(si.p, si.ng, s.ray.d);
        return no_shadow_ray();
      }
      s.radiance += eval_emitter_surface(si);
    }
    Material m = scene_material(si.material);
    s.anchor_frame = si.frame;
    s.anchor_p = si.p;
    s.anchor_ng = si.ng;
    s.anchor_wi = si.wi;
    s.anchor_uv = si.uv;
    s.anchor_material = si.material;
    s.anchor_smooth = (bsdf_flags(m, si.uv) & BSDF_SMOOTH) != 0u ? 1u : 0u;
  } else if (any(notEqual(s.throughput, vec3(0.0f)))) {
    direct_score_bsdf_hit(s, hit, it);
  }
  if (s.stage == rounds) {
    s.alive = 0u;
    return no_shadow_ray();
  }
  ShadowRay sr = direct_round(s, s.stage, it);
  s.stage += 1u;
  return sr;
}

TR_NAMESPACE_END

#endif
