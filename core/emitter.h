// Emitter sampling and evaluation over all emitters of the scene. One emitter is chosen
// with probability proportional to its `sampling_weight` (the scene's emitter alias table),
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
#include "core/rng.h"

TR_NAMESPACE_BEGIN

INLINE EmitterSample sample_emitter(vec3 ref_p, INOUT(Rng) rng) {
  SceneGlobals g = scene_globals();
  if (g.emitter_count == 0u) return emitter_sample_failed();
  float pmf;
  uint index = alias_sample(g.emitter_alias_offset, g.emitter_count, rng_next_2d(rng), pmf);
  Emitter e = scene_emitter(index);
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
INLINE float pdf_emitter_surface(vec3 ref_p, SurfaceInteraction si) {
  Emitter e = scene_emitter(si.emitter);
  return alias_pmf(scene_globals().emitter_alias_offset, si.emitter) *
         pdf_area_emitter(e, ref_p, si.p, si.frame.n);
}

// Radiance an area emitter hit sends back along si.wi.
INLINE vec3 eval_emitter_surface(SurfaceInteraction si) {
  return eval_area_emitter(scene_emitter(si.emitter), si.wi);
}

// The environment (constant or envmap) seen along direction d; zero without one.
INLINE vec3 eval_environment(vec3 d) {
  SceneGlobals g = scene_globals();
  if (g.environment == NO_INDEX) return vec3(0.0f);
  Emitter e = scene_emitter(g.environment);
  if (TR_HAS_EMITTER(EMITTER_CONSTANT) && e.type == EMITTER_CONSTANT) return e.radiance;
  if (TR_HAS_EMITTER(EMITTER_ENVMAP) && e.type == EMITTER_ENVMAP) return eval_envmap_emitter(e, d);
  return vec3(0.0f);
}

// Density of sample_emitter producing direction d through the environment.
INLINE float pdf_environment(vec3 d) {
  SceneGlobals g = scene_globals();
  if (g.environment == NO_INDEX) return 0.0f;
  Emitter e = scene_emitter(g.environment);
  float pmf = alias_pmf(g.emitter_alias_offset, g.environment);
  if (TR_HAS_EMITTER(EMITTER_CONSTANT) && e.type == EMITTER_CONSTANT)
    return pmf * pdf_constant_emitter();
  if (TR_HAS_EMITTER(EMITTER_ENVMAP) && e.type == EMITTER_ENVMAP)
    return pmf * pdf_envmap_emitter(e, d);
  return 0.0f;
}

TR_NAMESPACE_END

#endif
