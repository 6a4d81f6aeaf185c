// Mitsuba 3 `pplastic` (src/bsdfs/pplastic.cpp) as its unpolarized variants (scalar_rgb)
// render it: a rough specular reflection added to a Lambertian base seen through two smooth
// refractions (Baek et al., "Simultaneous Acquisition of Polarimetric SVBRDF and Normals",
// SIGGRAPH Asia 2018, with the Mueller matrices reduced to their intensity terms), lit from
// the front side:
//   f cos_o = R_s F(wi.h) D(h) G(wi, wo, h) / (4 cos_i)                  (Walter et al. 2007)
//           + R_d (1 - F(cos_i)) (1 - F(cos_o)) cos_o / pi
// F the unpolarized dielectric reflectance for the relative IOR eta. Unlike roughplastic there
// is no internal scattering series: the sum is not energy conserving, nor meant to be.
// Sampling chooses the microfacet lobe with the fixed probability w = s_mean / (d_mean +
// s_mean) over the reflectance textures (Material.extra), else the cosine-weighted
// hemisphere; pdf and weight are those of the mixture, as in Mitsuba.
#ifndef TWINRAY_CORE_BSDF_PPLASTIC_H
#define TWINRAY_CORE_BSDF_PPLASTIC_H

#include "core/bsdf/common.h"
#include "core/fresnel.h"
#include "core/material_slots.h"
#include "core/microfacet.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

INLINE uint pplastic_flags(IN(Material) m, TexCoord uv) {
  return BSDF_GLOSSY_REFLECTION | BSDF_DIFFUSE_REFLECTION;
}

INLINE Microfacet pplastic_distribution(IN(Material) m, TexCoord uv) {
  return microfacet_make((m.flags & MATERIAL_BECKMANN) != 0u, m.param[PPLASTIC_ALPHA_U].value.x,
                         m.param[PPLASTIC_ALPHA_V].value.x,
                         (m.flags & MATERIAL_SAMPLE_VISIBLE) != 0u);
}

INLINE BsdfEvalPdf pplastic_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  if (wi.z <= 0.0f || wo.z <= 0.0f) return bsdf_eval_pdf_zero();
  float eta = m.param[PPLASTIC_ETA].value.x;
  Microfacet d = pplastic_distribution(m, uv);
  vec3 h = normalize(wo + wi);
  float specular = fresnel_dielectric_reflectance(dot(wi, h), eta) * microfacet_d(d, h) *
                   microfacet_g(d, wi, wo, h) / (4.0f * wi.z);
  float transmitted = (1.0f - fresnel_dielectric_reflectance(wi.z, eta)) *
                      (1.0f - fresnel_dielectric_reflectance(wo.z, eta));
  float specular_pdf = 0.0f;
  if (dot(wi, h) > 0.0f && dot(wo, h) > 0.0f)
    // Half-vector density times dh/dwo = 1 / (4 wo.h) (Walter et al. 2007, eq. 14).
    specular_pdf = microfacet_pdf(d, wi, h) / (4.0f * dot(wo, h));
  return bsdf_eval_pdf_make(
      m.param[PLASTIC_SPECULAR_REFLECTANCE].value * specular +
          m.param[PLASTIC_DIFFUSE_REFLECTANCE].value * (transmitted * INV_PI * wo.z),
      m.extra * specular_pdf + (1.0f - m.extra) * square_to_cosine_hemisphere_pdf(wo));
}

INLINE BsdfSample pplastic_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  if (wi.z <= 0.0f) return bsdf_sample_failed();
  bool specular = u1 < m.extra;
  vec3 wo = specular ? reflect_about(wi, microfacet_sample(pplastic_distribution(m, uv), wi, u2))
                     : square_to_cosine_hemisphere(u2);
  if (!(wo.z > 0.0f)) return bsdf_sample_failed();
  return bsdf_sample_smooth(wo, pplastic_eval_pdf(m, uv, wi, wo), 1.0f,
                            specular ? BSDF_GLOSSY_REFLECTION : BSDF_DIFFUSE_REFLECTION);
}

TR_NAMESPACE_END

#endif
