// Orthonormal shading frame; local coordinates have the normal along +z.
// Basis construction: Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1) 2017.
#ifndef TWINRAY_CORE_FRAME_H
#define TWINRAY_CORE_FRAME_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

struct Frame {
  vec3 s;
  vec3 t;
  vec3 n;
};

INLINE Frame frame_from_normal(vec3 n) {
  float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (sgn + n.z);
  float b = n.x * n.y * a;
  Frame f;
  f.s = vec3(1.0f + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  f.t = vec3(b, sgn + n.y * n.y * a, -n.y);
  f.n = n;
  return f;
}

INLINE vec3 frame_to_local(Frame f, vec3 v) { return vec3(dot(v, f.s), dot(v, f.t), dot(v, f.n)); }
INLINE vec3 frame_to_world(Frame f, vec3 v) { return f.s * v.x + f.t * v.y + f.n * v.z; }

// Spherical-coordinate helpers on local directions (pbrt-v4 §3.8.3).
INLINE float cos_theta(vec3 w) { return w.z; }
INLINE float cos2_theta(vec3 w) { return w.z * w.z; }
INLINE float sin2_theta(vec3 w) { return max(0.0f, 1.0f - w.z * w.z); }
INLINE float sin_theta(vec3 w) { return sqrt(sin2_theta(w)); }
INLINE float tan2_theta(vec3 w) { return sin2_theta(w) / cos2_theta(w); }
INLINE float cos_phi(vec3 w) {
  float st = sin_theta(w);
  return st == 0.0f ? 1.0f : clamp(w.x / st, -1.0f, 1.0f);
}
INLINE float sin_phi(vec3 w) {
  float st = sin_theta(w);
  return st == 0.0f ? 0.0f : clamp(w.y / st, -1.0f, 1.0f);
}

TR_NAMESPACE_END

#endif
