// Mitsuba 3 `normalmap` (src/bsdfs/normalmap.cpp, normalmap_helpers.h): the nested BSDF is
// evaluated in a perturbed frame whose normal is decoded from the texture, n = 2 rgb - 1,
// relative to the shading frame. With flip_invalid_normals (default true), a normal on the
// other side of wi than the shading normal (cos theta_i * dot(wi, n) <= 0) is mirrored to
// (-n.x, -n.y, n.z). The frame's tangent is (1, 0, 0) made orthogonal to n (Gram-Schmidt), its
// bitangent n x s. eval, pdf and the sampled direction are zero unless wo lies on the same side
// of the shading and of the perturbed surface; with use_shadowing_function (default true) the
// value is scaled by the shadowing term of Estevez et al., "A Microfacet-Based Shadowing
// Function to Solve the Bump Terminator Problem" (Ray Tracing Gems, 2019):
//   alpha^2 = min(tan^2 theta_n / 8, 1),   G = 2 / (1 + sqrt(1 + alpha^2 tan^2 theta_o)).
// Where Mitsuba divides by zero (a texel decoding to n = 0, or n = (+-1, 0, 0) that leaves no
// tangent), the shading frame is used unperturbed or completed by frame_from_normal.
#ifndef TWINRAY_CORE_BSDF_NORMALMAP_H
#define TWINRAY_CORE_BSDF_NORMALMAP_H

#include "core/bsdf/common.h"
#include "core/bsdf/perturbed_frame.h"
#include "core/frame.h"
#include "core/material_slots.h"

TR_NAMESPACE_BEGIN

INLINE uint normalmap_child(IN(Material) m) { return uint(m.param[NORMALMAP_BSDF].value.x); }

INLINE bool normalmap_shadowing(IN(Material) m) {
  return m.param[NORMALMAP_OPTIONS].value.y != 0.0f;
}

// The perturbed frame relative to the shading frame, for incident direction wi.
INLINE Frame normalmap_frame(IN(Material) m, TexCoord uv, vec3 wi) {
  vec3 n = eval_textured(m.param[NORMALMAP_NORMALMAP], uv) * 2.0f - vec3(1.0f);
  n = perturbed_normal_flipped(n, wi, m.param[NORMALMAP_OPTIONS].value.x != 0.0f);
  float len2 = dot(n, n);
  if (!(len2 > 0.0f)) return frame_from_normal(vec3(0.0f, 0.0f, 1.0f));
  return perturbed_frame(n * inversesqrt(len2), vec3(1.0f, 0.0f, 0.0f));
}

// Estevez et al.'s shadowing term for the perturbed normal n and wo, both in the shading frame.
INLINE float normalmap_shadow_terminator(vec3 n, vec3 wo) {
  float alpha2 = min(0.125f * tan2_theta(n), 1.0f);
  return 2.0f / (1.0f + sqrt(1.0f + alpha2 * tan2_theta(wo)));
}

TR_NAMESPACE_END

#endif
