// Mitsuba 3 `dielectric` (src/bsdfs/dielectric.cpp): a smooth interface between two
// dielectrics, lit from both sides. Reflection is chosen with probability F (exact dielectric
// Fresnel), refraction with 1 - F, so the sampled weight is specular_reflectance or
// specular_transmittance; refracted radiance is scaled by eta_ti^2 = (n_i / n_t)^2 for the
// solid-angle compression at the interface (Veach 1997, §5.2; pbrt-v4 §9.5.2).
#ifndef TWINRAY_CORE_BSDF_DIELECTRIC_H
#define TWINRAY_CORE_BSDF_DIELECTRIC_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"

TR_NAMESPACE_BEGIN

INLINE uint dielectric_flags(IN(Material) m, TexCoord uv) {
  return BSDF_DELTA_REFLECTION | BSDF_DELTA_TRANSMISSION;
}

INLINE BsdfSample dielectric_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  float cos_theta_t;
  float eta_it;
  float eta_ti;
  float r = fresnel_dielectric(wi.z, m.eta, cos_theta_t, eta_it, eta_ti);
  if (u1 <= r) {
    return bsdf_sample_make(reflect_local(wi), r, m.param[DIELECTRIC_SPECULAR_REFLECTANCE].value,
                            1.0f, BSDF_DELTA_REFLECTION);
  }
  vec3 weight = m.param[DIELECTRIC_SPECULAR_TRANSMITTANCE].value * (eta_ti * eta_ti);
  return bsdf_sample_make(refract_local(wi, cos_theta_t, eta_ti), 1.0f - r, weight, eta_it,
                          BSDF_DELTA_TRANSMISSION);
}

TR_NAMESPACE_END

#endif
