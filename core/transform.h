// Row-major 3x4 affine transforms stored as three vec4 rows (core/scene_types.h).
#ifndef TWINRAY_CORE_TRANSFORM_H
#define TWINRAY_CORE_TRANSFORM_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

INLINE vec3 transform_point(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
  vec4 h = vec4(p, 1.0f);
  return vec3(dot(r0, h), dot(r1, h), dot(r2, h));
}

INLINE vec3 transform_vector(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
  return vec3(dot(vec3(r0), v), dot(vec3(r1), v), dot(vec3(r2), v));
}

// Normals transform by the inverse transpose: n' = M^-T n, where (r0, r1, r2) are the rows
// of the inverse M^-1; its transpose's rows are the columns of M^-1.
INLINE vec3 transform_normal(vec4 inv_r0, vec4 inv_r1, vec4 inv_r2, vec3 n) {
  return vec3(inv_r0.x * n.x + inv_r1.x * n.y + inv_r2.x * n.z,
              inv_r0.y * n.x + inv_r1.y * n.y + inv_r2.y * n.z,
              inv_r0.z * n.x + inv_r1.z * n.y + inv_r2.z * n.z);
}

TR_NAMESPACE_END

#endif
