// The shading frame of Mitsuba 3's normal-perturbing adapters (src/bsdfs/normalmap.cpp,
// bumpmap.cpp), relative to the shading frame: with flip_invalid_normals, a unit normal n on
// the other side of wi than the shading normal (cos theta_i * dot(wi, n) <= 0) is mirrored to
// (-n.x, -n.y, n.z); the tangent is a reference direction made orthogonal to n (Gram-Schmidt),
// the bitangent n x s. Where Mitsuba divides by zero (the reference direction parallel to n),
// the frame is completed by frame_from_normal.
#ifndef TWINRAY_CORE_BSDF_PERTURBED_FRAME_H
#define TWINRAY_CORE_BSDF_PERTURBED_FRAME_H

#include "core/frame.h"

TR_NAMESPACE_BEGIN

INLINE vec3 perturbed_normal_flipped(vec3 n, vec3 wi, bool flip_invalid_normals) {
  if (flip_invalid_normals && wi.z * dot(wi, n) <= 0.0f) return vec3(-n.x, -n.y, n.z);
  return n;
}

INLINE Frame perturbed_frame(vec3 n, vec3 reference_tangent) {
  vec3 s = reference_tangent - n * dot(n, reference_tangent);
  float s_len2 = dot(s, s);
  if (!(s_len2 > 0.0f)) return frame_from_normal(n);
  Frame f;
  f.n = n;
  f.s = s * inversesqrt(s_len2);
  f.t = cross(n, f.s);
  return f;
}

TR_NAMESPACE_END

#endif
