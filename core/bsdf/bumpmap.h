// Mitsuba 3 `bumpmap` (src/bsdfs/bumpmap.cpp): the nested BSDF is evaluated in a frame whose
// normal comes from displacing the surface along the shading normal n by scale * h(u, v):
//   dp/du' = dp/du + n (scale dh/du - <n, dp/du>),   dp/dv' = dp/dv + n (scale dh/dv - <n, dp/dv>),
//   n' = normalize(dp/du' x dp/dv'), turned to the side of the geometric normal,
// then flipped toward wi and completed with the tangent dp/du (core/bsdf/perturbed_frame.h).
// The gradient dh/duv is the texture's eval_1_grad (core/texture.h). The visibility test and
// the shadowing term are normalmap's (core/bsdf.h). Where Mitsuba divides by zero
// (dp/du' parallel to dp/dv', e.g. at a sphere's pole) or overflows, the shading frame is kept.
#ifndef TWINRAY_CORE_BSDF_BUMPMAP_H
#define TWINRAY_CORE_BSDF_BUMPMAP_H

#include "core/bsdf/common.h"
#include "core/bsdf/perturbed_frame.h"
#include "core/material_slots.h"
#include "core/texture.h"

TR_NAMESPACE_BEGIN

// The surface's differential geometry at a BSDF query, in the shading frame: the position's
// partial derivatives dp/du, dp/dv and the geometric normal.
struct BsdfSurface {
  vec3 dp_du;
  vec3 dp_dv;
  vec3 ng;
};

// A plane parameterized by the shading frame's tangents: the surface of BSDF tests.
INLINE BsdfSurface bsdf_surface_flat() {
  BsdfSurface g;
  g.dp_du = vec3(1.0f, 0.0f, 0.0f);
  g.dp_dv = vec3(0.0f, 1.0f, 0.0f);
  g.ng = vec3(0.0f, 0.0f, 1.0f);
  return g;
}

INLINE vec2 bumpmap_gradient(IN(Material) m, TexCoord uv) {
  return m.param[BUMPMAP_OPTIONS].value.z *
         eval_texture_1_grad(m.param[BUMPMAP_HEIGHT].texture, uv.uv);
}

// The perturbed frame relative to the shading frame, for incident direction wi.
INLINE Frame bumpmap_frame(IN(Material) m, IN(BsdfSurface) g, TexCoord uv, vec3 wi) {
  vec2 grad = bumpmap_gradient(m, uv);
  vec3 dp_du = vec3(g.dp_du.x, g.dp_du.y, grad.x);
  vec3 dp_dv = vec3(g.dp_dv.x, g.dp_dv.y, grad.y);
  vec3 n = cross(dp_du, dp_dv);
  // Divided by its largest component first, so that a steep gradient does not overflow |n|^2.
  float n_max = max(max(abs(n.x), abs(n.y)), abs(n.z));
  if (!(n_max > 0.0f) || isinf(n_max)) return frame_from_normal(vec3(0.0f, 0.0f, 1.0f));
  n = normalize(n / n_max);
  if (dot(g.ng, n) < 0.0f) n = -n;
  n = perturbed_normal_flipped(n, wi, m.param[BUMPMAP_OPTIONS].value.x != 0.0f);
  return perturbed_frame(n, g.dp_du);
}

TR_NAMESPACE_END

#endif
