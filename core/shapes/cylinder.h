// Open cylinder of radius 1 around the z axis, z in [0, 1] (object space of SHAPE_CYLINDER).
#ifndef TWINRAY_CORE_SHAPES_CYLINDER_H
#define TWINRAY_CORE_SHAPES_CYLINDER_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// Nearest root of x^2 + y^2 = 1 with z in [0, 1], stable quadratic (Numerical Recipes §5.6).
INLINE bool intersect_unit_cylinder(vec3 o, vec3 d, float tmin, float tmax, OUT(float) t) {
  float a = d.x * d.x + d.y * d.y;
  if (a == 0.0f) return false;
  float b = o.x * d.x + o.y * d.y;
  float c = o.x * o.x + o.y * o.y - 1.0f;
  float disc = b * b - a * c;
  if (disc < 0.0f) return false;
  float q = -(b + (b >= 0.0f ? 1.0f : -1.0f) * sqrt(disc));
  float t0 = c / q;
  float t1 = q / a;
  if (q == 0.0f) {
    t0 = 0.0f;
    t1 = 0.0f;
  }
  if (t0 > t1) {
    float tmp = t0;
    t0 = t1;
    t1 = tmp;
  }
  float z0 = o.z + t0 * d.z;
  if (t0 > tmin && t0 < tmax && z0 >= 0.0f && z0 <= 1.0f) {
    t = t0;
    return true;
  }
  float z1 = o.z + t1 * d.z;
  if (t1 > tmin && t1 < tmax && z1 >= 0.0f && z1 <= 1.0f) {
    t = t1;
    return true;
  }
  return false;
}

// Mitsuba's cylinder parameterization: u = phi / 2pi, v = z.
INLINE vec2 unit_cylinder_uv(vec3 p) {
  float phi = atan(p.y, p.x);
  if (phi < 0.0f) phi += 2.0f * PI;
  return vec2(phi * INV_TWO_PI, p.z);
}

TR_NAMESPACE_END

#endif
