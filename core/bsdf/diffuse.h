// Mitsuba 3 `diffuse` (src/bsdfs/diffuse.cpp): Lambertian reflection f = reflectance / pi on
// the front side only, sampled with the cosine-weighted hemisphere (pbrt-v4 §9.2).
#ifndef TWINRAY_CORE_BSDF_DIFFUSE_H
#define TWINRAY_CORE_BSDF_DIFFUSE_H

#include "core/bsdf/common.h"
#include "core/material_slots.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

INLINE uint diffuse_flags(IN(Material) m, TexCoord uv) { return BSDF_DIFFUSE_REFLECTION; }

INLINE BsdfEvalPdf diffuse_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  if (wi.z <= 0.0f || wo.z <= 0.0f) return bsdf_eval_pdf_zero();
  return bsdf_eval_pdf_make(m.param[DIFFUSE_REFLECTANCE].value * (INV_PI * wo.z),
                            square_to_cosine_hemisphere_pdf(wo));
}

INLINE BsdfSample diffuse_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  if (wi.z <= 0.0f) return bsdf_sample_failed();
  vec3 wo = square_to_cosine_hemisphere(u2);
  float pdf = square_to_cosine_hemisphere_pdf(wo);
  if (pdf <= 0.0f) return bsdf_sample_failed();
  // f cos / pdf = (reflectance / pi) cos / (cos / pi) = reflectance.
  return bsdf_sample_make(wo, pdf, m.param[DIFFUSE_REFLECTANCE].value, 1.0f,
                          BSDF_DIFFUSE_REFLECTION);
}

TR_NAMESPACE_END

#endif
