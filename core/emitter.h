// Emitter sampling and evaluation over all emitters of the scene. One emitter is chosen by the
// scene's emitter selection (EMITTER_SELECTION_*; Mitsuba's: proportional to `sampling_weight`)
// then sampled by its own strategy; densities include the selection probability.
#ifndef TWINRAY_CORE_EMITTER_H
#define TWINRAY_CORE_EMITTER_H

#include "core/alias.h"
#include "core/emitters/area.h"
#include "core/emitters/constant.h"
#include "core/emitters/directional.h"
#include "core/emitters/envmap.h"
#include "core/emitters/point.h"
#include "core/emitters/projector.h"
#include "core/emitters/spot.h"
#include "core/interaction.h"
#include "core/light_bvh.h"
#include "core/rng.h"

TR_NAMESPACE_BEGIN

// Chooses the emitter a light sample from ref_p starts from, with its probability in pmf
// (NO_INDEX when none can light ref_p). One 2D number whatever the selection: u.x picks, u.y is
// an alias table's second choice.
INLINE uint select_emitter(IN(SceneGlobals) g, vec3 ref_p, vec2 u, OUT(float) pmf) {
  if (!TR_HAS_EMITTER_SELECTION(EMITTER_SELECTION_BVH) ||
      g.emitter_selection != EMITTER_SELECTION_BVH)
    return alias_sample(g.emitter_alias_offset, g.emitter_count, u, pmf);
  float p_inf = g.infinite_probability;
  if (u.x < p_inf) {
    u.x = min(u.x / p_inf, ONE_MINUS_EPSILON);
    uint index = alias_sample(g.infinite_alias_offset, g.emitter_count, u, pmf);
    pmf *= p_inf;
    return index;
  }
  uint index = light_bvh_sample(g.light_root, ref_p,
                                min((u.x - p_inf) / (1.0f - p_inf), ONE_MINUS_EPSILON), pmf);
  pmf *= 1.0f - p_inf;
  return index;
}

// The probability with which select_emitter chooses emitter `index` from ref_p.
INLINE float emitter_pmf(IN(SceneGlobals) g, vec3 ref_p, uint index) {
  if (!TR_HAS_EMITTER_SELECTION(EMITTER_SELECTION_BVH) ||
      g.emitter_selection != EMITTER_SELECTION_BVH)
    return alias_pmf(g.emitter_alias_offset, index);
  float pmf = 0.0f;
  if (g.infinite_probability > 0.0f)
    pmf += g.infinite_probability * alias_pmf(g.infinite_alias_offset, index);
  if (g.infinite_probability < 1.0f)
    pmf += (1.0f - g.infinite_probability) *
           light_bvh_pmf(g.light_root, ref_p, scene_emitter(index).light_leaf);
  return pmf;
}

INLINE EmitterSample sample_emitter(vec3 ref_p, INOUT(Rng) rng) {
  REF(SceneGlobals) g = scene_globals();
  if (g.emitter_count == 0u) return emitter_sample_failed();
  float pmf;
  uint index = select_emitter(g, ref_p, rng_next_2d(rng), pmf);
  if (index == NO_INDEX) return emitter_sample_failed();
  REF(Emitter) e = scene_emitter(index);
  EmitterSample s = emitter_sample_failed();
  if (TR_HAS_EMITTER(EMITTER_AREA) && e.type == EMITTER_AREA) {
    s = sample_area_emitter(e, ref_p, rng);
  } else if (TR_HAS_EMITTER(EMITTER_POINT) && e.type == EMITTER_POINT) {
    s = sample_point_emitter(e, ref_p);
  } else if (TR_HAS_EMITTER(EMITTER_SPOT) && e.type == EMITTER_SPOT) {
    s = sample_spot_emitter(e, ref_p);
  } else if (TR_HAS_EMITTER(EMITTER_PROJECTOR) && e.type == EMITTER_PROJECTOR) {
    s = sample_projector_emitter(e, ref_p);
  } else if (TR_HAS_EMITTER(EMITTER_DIRECTIONAL) && e.type == EMITTER_DIRECTIONAL) {
    s = sample_directional_emitter(e, ref_p);
  } else if (TR_HAS_EMITTER(EMITTER_CONSTANT) && e.type == EMITTER_CONSTANT) {
    s = sample_constant_emitter(e, ref_p, rng_next_2d(rng));
  } else if (TR_HAS_EMITTER(EMITTER_ENVMAP) && e.type == EMITTER_ENVMAP) {
    vec2 u_cell = rng_next_2d(rng);
    s = sample_envmap_emitter(e, ref_p, u_cell, rng_next_2d(rng));
  }
  s.emitter = index;
  if (!(s.pdf > 0.0f) || !(pmf > 0.0f)) return emitter_sample_failed();
  s.pdf *= pmf;
  s.weight /= pmf;
  return s;
}

// Density of sample_emitter producing the surface point of `si` (an area emitter hit)
// from ref_p.
INLINE float pdf_emitter_surface(vec3 ref_p, IN(SurfaceInteraction) si) {
  REF(Emitter) e = scene_emitter(si.emitter);
  return emitter_pmf(scene_globals(), ref_p, si.emitter) *
         pdf_area_emitter(e, ref_p, si.p, si.frame.n);
}

// Radiance an area emitter hit sends back along si.wi.
INLINE vec3 eval_emitter_surface(IN(SurfaceInteraction) si) {
  return eval_area_emitter(scene_emitter(si.emitter), si.wi, si.uv);
}

// The environment (constant or envmap) seen along direction d; zero without one.
INLINE vec3 eval_environment(vec3 d) {
  REF(SceneGlobals) g = scene_globals();
  if (g.environment == NO_INDEX) return vec3(0.0f);
  REF(Emitter) e = scene_emitter(g.environment);
  if (TR_HAS_EMITTER(EMITTER_CONSTANT) && e.type == EMITTER_CONSTANT) return e.radiance;
  if (TR_HAS_EMITTER(EMITTER_ENVMAP) && e.type == EMITTER_ENVMAP) return eval_envmap_emitter(e, d);
  return vec3(0.0f);
}

// Density of sample_emitter producing direction d through the environment.
INLINE float pdf_environment(vec3 d) {
  REF(SceneGlobals) g = scene_globals();
  if (g.environment == NO_INDEX) return 0.0f;
  REF(Emitter) e = scene_emitter(g.environment);
  // An infinite emitter's selection does not depend on the reference point.
  float pmf = emitter_pmf(g, vec3(0.0f), g.environment);
  if (TR_HAS_EMITTER(EMITTER_CONSTANT) && e.type == EMITTER_CONSTANT)
    return pmf * pdf_constant_emitter();
  if (TR_HAS_EMITTER(EMITTER_ENVMAP) && e.type == EMITTER_ENVMAP)
    return pmf * pdf_envmap_emitter(e, d);
  return 0.0f;
}

TR_NAMESPACE_END

#endif
