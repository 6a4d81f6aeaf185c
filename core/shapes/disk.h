// Unit disk in the z = 0 plane, normal +z (object space of SHAPE_DISK).
#ifndef TWINRAY_CORE_SHAPES_DISK_H
#define TWINRAY_CORE_SHAPES_DISK_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

INLINE bool intersect_unit_disk(vec3 o, vec3 d, float tmin, float tmax, OUT(float) t) {
  if (d.z == 0.0f) return false;
  float th = -o.z / d.z;
  if (!(th > tmin && th < tmax)) return false;
  vec2 p = vec2(o.x, o.y) + th * vec2(d.x, d.y);
  if (dot(p, p) > 1.0f) return false;
  t = th;
  return true;
}

// Mitsuba's disk parameterization: u = r, v = phi / 2pi.
INLINE vec2 unit_disk_uv(vec3 p) {
  float phi = atan(p.y, p.x);
  if (phi < 0.0f) phi += 2.0f * PI;
  return vec2(length(vec2(p.x, p.y)), phi * INV_TWO_PI);
}

TR_NAMESPACE_END

#endif
