// Rays, and origins offset off surfaces so that spawned rays never re-hit their own surface.
#ifndef TWINRAY_CORE_RAY_H
#define TWINRAY_CORE_RAY_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

struct Ray {
  vec3 o;
  float tmin;
  vec3 d;
  float tmax;
};

INLINE Ray make_ray(vec3 o, vec3 d, float tmax) {
  Ray r;
  r.o = o;
  r.tmin = 0.0f;
  r.d = d;
  r.tmax = tmax;
  return r;
}

// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing
// Gems ch. 6 (2019), Listing 6-1: move p along the geometric normal n by a fixed number of
// ulps far from the origin and by a fixed distance near it.
INLINE vec3 offset_ray_origin(vec3 p, vec3 n) {
  const float origin = 1.0f / 32.0f;
  const float float_scale = 1.0f / 65536.0f;
  const float int_scale = 256.0f;
  ivec3 of_i = ivec3(int_scale * n.x, int_scale * n.y, int_scale * n.z);
  vec3 p_i = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0f ? -of_i.x : of_i.x)),
                  intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0f ? -of_i.y : of_i.y)),
                  intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0f ? -of_i.z : of_i.z)));
  return vec3(abs(p.x) < origin ? p.x + float_scale * n.x : p_i.x,
              abs(p.y) < origin ? p.y + float_scale * n.y : p_i.y,
              abs(p.z) < origin ? p.z + float_scale * n.z : p_i.z);
}

// Spawns a ray leaving p in direction d: the origin moves to the side of the geometric
// normal ng that d points into.
INLINE Ray spawn_ray(vec3 p, vec3 ng, vec3 d) {
  vec3 n = dot(d, ng) >= 0.0f ? ng : -ng;
  return make_ray(offset_ray_origin(p, n), d, FLOAT_MAX);
}

// Shadow-ray fraction of the distance to the target kept, so the target surface itself
// is not reported as an occluder.
const float SHADOW_EPSILON = 1e-4f;

// Spawns a ray from p towards the point target (offset off its own surface normal n_target
// when that is nonzero), stopping just short of it.
INLINE Ray spawn_ray_to(vec3 p, vec3 ng, vec3 target, vec3 n_target) {
  vec3 d0 = target - p;
  vec3 n = dot(d0, ng) >= 0.0f ? ng : -ng;
  vec3 o = offset_ray_origin(p, n);
  vec3 t = target;
  if (dot(n_target, n_target) > 0.0f)
    t = offset_ray_origin(target, dot(d0, n_target) > 0.0f ? -n_target : n_target);
  vec3 d = t - o;
  float dist = length(d);
  return make_ray(o, d / dist, dist * (1.0f - SHADOW_EPSILON));
}

TR_NAMESPACE_END

#endif
