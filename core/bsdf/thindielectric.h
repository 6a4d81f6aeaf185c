// Mitsuba 3 `thindielectric` (src/bsdfs/thindielectric.cpp): a thin dielectric slab with
// parallel faces, lit from both sides. Summing the internal reflections between its two
// interfaces (each reflecting R = F(|cos_i|), transmitting T = 1 - R) gives
//   R' = R + T^2 R / (1 - R^2) = 2 R / (1 + R),   T' = 1 - R'
// (Mitsuba's derivation; pbrt-v4 §9.5.3 ThinDielectricBxDF). Light passes straight through
// (wo = -wi, a null lobe: no refraction, eta 1), or reflects; the lobe is chosen with
// probability R' so the weight is the tint alone.
#ifndef TWINRAY_CORE_BSDF_THINDIELECTRIC_H
#define TWINRAY_CORE_BSDF_THINDIELECTRIC_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"

TR_NAMESPACE_BEGIN

INLINE uint thindielectric_flags(IN(Material) m, TexCoord uv) {
  return BSDF_DELTA_REFLECTION | BSDF_NULL;
}

INLINE BsdfSample thindielectric_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  float r = fresnel_dielectric_reflectance(abs(wi.z), m.eta);
  r *= 2.0f / (1.0f + r);
  if (u1 <= r) {
    return bsdf_sample_make(reflect_local(wi), r, m.param[DIELECTRIC_SPECULAR_REFLECTANCE].value,
                            1.0f, BSDF_DELTA_REFLECTION);
  }
  return bsdf_sample_make(-wi, 1.0f - r, m.param[DIELECTRIC_SPECULAR_TRANSMITTANCE].value, 1.0f,
                          BSDF_NULL);
}

TR_NAMESPACE_END

#endif
