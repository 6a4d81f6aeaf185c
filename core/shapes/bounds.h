// World-space box of an analytic shape: the corners of its unit shape's object-space box (sphere
// [-1, 1]^3, disk [-1, 1]^2 x {0}, cylinder [-1, 1]^2 x [0, 1]) through to_world, unpadded
// (each user pads it for its own rounding).
#ifndef TWINRAY_CORE_SHAPES_BOUNDS_H
#define TWINRAY_CORE_SHAPES_BOUNDS_H

#include "core/scene_types.h"
#include "core/transform.h"

TR_NAMESPACE_BEGIN

INLINE void analytic_shape_bounds(IN(Shape) s, OUT(vec3) lower, OUT(vec3) upper) {
  vec3 lo = vec3(-1.0f, -1.0f, s.type == SHAPE_SPHERE ? -1.0f : 0.0f);
  vec3 hi = vec3(1.0f, 1.0f, s.type == SHAPE_DISK ? 0.0f : 1.0f);
  lower = vec3(FLOAT_MAX);
  upper = vec3(-FLOAT_MAX);
  for (int corner = 0; corner < 8; ++corner) {
    vec3 c = vec3((corner & 1) != 0 ? hi.x : lo.x, (corner & 2) != 0 ? hi.y : lo.y,
                  (corner & 4) != 0 ? hi.z : lo.z);
    vec3 p = transform_point(s.to_world[0], s.to_world[1], s.to_world[2], c);
    lower = min(lower, p);
    upper = max(upper, p);
  }
}

TR_NAMESPACE_END

#endif
