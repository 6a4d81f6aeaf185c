// Mitsuba 3 `conductor` (src/bsdfs/conductor.cpp): a perfectly smooth metal, a delta
// reflection lit from the front side, weighted by specular_reflectance times the exact
// conductor Fresnel reflectance (core/fresnel.h). eta = 0, k = 1 (Mitsuba's defaults)
// reflect everything.
#ifndef TWINRAY_CORE_BSDF_CONDUCTOR_H
#define TWINRAY_CORE_BSDF_CONDUCTOR_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"

TR_NAMESPACE_BEGIN

INLINE uint conductor_flags(IN(Material) m, TexCoord uv) { return BSDF_DELTA_REFLECTION; }

INLINE vec3 conductor_fresnel(IN(Material) m, TexCoord uv, float cos_theta_i) {
  return fresnel_conductor(cos_theta_i, m.param[CONDUCTOR_ETA].value, m.param[CONDUCTOR_K].value) *
         m.param[CONDUCTOR_SPECULAR_REFLECTANCE].value;
}

INLINE BsdfSample conductor_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  if (wi.z <= 0.0f) return bsdf_sample_failed();
  return bsdf_sample_make(reflect_local(wi), 1.0f, conductor_fresnel(m, uv, wi.z), 1.0f,
                          BSDF_DELTA_REFLECTION);
}

TR_NAMESPACE_END

#endif
