// State of one camera sample while a backend traces its rays: the next ray to trace, the
// running estimate, and what the integrators carry from one vertex to the next.
#ifndef TWINRAY_CORE_INTEGRATORS_PATH_STATE_H
#define TWINRAY_CORE_INTEGRATORS_PATH_STATE_H

#include "core/frame.h"
#include "core/ray.h"
#include "core/rng.h"
#include "core/texture.h"

TR_NAMESPACE_BEGIN

// A surface point where light is sampled: the path's current vertex, or the direct
// integrator's first hit, which all of its sampling rounds share.
struct ShadingPoint {
  Frame frame;  // shading frame
  vec3 p;
  uint material;
  vec3 ng;  // geometric normal
  uint pad0;
  vec3 wi;  // towards the previous vertex, local to frame
  float pad1;
  TexCoord tex;  // where its textures are evaluated
  vec3 dp_du;    // world space
  vec3 dp_dv;
};

struct PathState {
  Ray ray;               // next ray to trace
  vec3 throughput;       // weight of what `ray` finds (path: product of BSDF weights;
                         // direct: the pending BSDF sample's weight)
  float eta;             // product of relative IORs crossed (Russian roulette, Mitsuba)
  vec3 radiance;         // estimate so far
  float prev_bsdf_pdf;   // solid-angle pdf of the BSDF sample that produced `ray`
  vec3 prev_p;           // the vertex `ray` leaves from
  uint prev_bsdf_delta;  // whether that BSDF sample came from a delta (or null) lobe
  Rng rng;
  uint depth;  // scattering events so far (Mitsuba's `depth`; path)
  uint alive;
  uint stage;           // direct: 0 for the camera ray, k for the k-th sampling round
  float film_sign;      // +1 or -1: the sample's sign in its pixel's estimate (core/film.h)
  ShadingPoint anchor;  // direct: the camera ray's hit
};

// A shadow ray a backend must trace; if nothing blocks it, the contribution is added.
struct ShadowRay {
  Ray ray;
  vec3 contribution;
  uint enabled;  // 0: nothing to trace
};

INLINE ShadowRay no_shadow_ray() {
  ShadowRay sr;
  sr.ray = make_ray(vec3(0.0f), vec3(0.0f, 0.0f, 1.0f), 0.0f);
  sr.contribution = vec3(0.0f);
  sr.enabled = 0u;
  return sr;
}

// Shadow ray from p (geometric normal ng) to an emitter sample's point, or towards an
// infinite emitter's direction.
INLINE Ray shadow_ray_to(vec3 p, vec3 ng, vec3 target, vec3 n_target, vec3 d, float dist) {
  if (dist == FLOAT_MAX) return spawn_ray(p, ng, d);
  return spawn_ray_to(p, ng, target, n_target);
}

TR_NAMESPACE_END

#endif
