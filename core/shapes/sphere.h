// Unit sphere at the origin (object space of SHAPE_SPHERE).
#ifndef TWINRAY_CORE_SHAPES_SPHERE_H
#define TWINRAY_CORE_SHAPES_SPHERE_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// Nearest root of |o + t d| = 1 in (tmin, tmax). Discriminant in the form of Haines et al.,
// "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7, eq. 10, and
// roots from the numerically stable quadratic formula (Press et al., Numerical Recipes §5.6).
INLINE bool intersect_unit_sphere(vec3 o, vec3 d, float tmin, float tmax, OUT(float) t) {
  float a = dot(d, d);
  float b = dot(o, d);
  vec3 l = o - (b / a) * d;
  float disc = a * (1.0f - dot(l, l));
  if (disc < 0.0f) return false;
  float c = dot(o, o) - 1.0f;
  float q = -(b + (b >= 0.0f ? 1.0f : -1.0f) * sqrt(disc));
  float t0 = c / q;
  float t1 = q / a;
  if (t0 > t1) {
    float tmp = t0;
    t0 = t1;
    t1 = tmp;
  }
  if (t0 > tmin && t0 < tmax) {
    t = t0;
    return true;
  }
  if (t1 > tmin && t1 < tmax) {
    t = t1;
    return true;
  }
  return false;
}

// Mitsuba's sphere parameterization: u = phi / 2pi, v = theta / pi (object space). theta as
// atan2(sin, cos): acos(p.z) loses digits near the poles, and GPU acos/asin approximations
// (lavapipe) lose about 1e-4 everywhere, while their atan2 is as accurate as the phi above.
INLINE vec2 unit_sphere_uv(vec3 p) {
  float phi = atan(p.y, p.x);
  if (phi < 0.0f) phi += 2.0f * PI;
  float theta = atan(length(vec2(p.x, p.y)), p.z);
  return vec2(phi * INV_TWO_PI, theta * INV_PI);
}

TR_NAMESPACE_END

#endif
