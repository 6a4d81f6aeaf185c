// Vocabulary shared by every BSDF in core/bsdf/: lobe flags, the sample record, and the
// conventions of the interface in core/bsdf.h. Directions are in the local shading frame
// (+z = shading normal); wi points toward the previous path vertex (Mitsuba's si.wi), wo
// toward the next one. Radiance transport only (Mitsuba's TransportMode::Radiance). The BSDFs
// of a leaf read their textured parameters as constants (`param[k].value`, the first channel of
// a scalar one): core/bsdf.h evaluates them at the shading point first (material_at).
#ifndef TWINRAY_CORE_BSDF_COMMON_H
#define TWINRAY_CORE_BSDF_COMMON_H

#include "core/prelude.h"
#include "core/scene_types.h"
#include "core/texture.h"

TR_NAMESPACE_BEGIN

// Lobe flags, Mitsuba 3 BSDFFlags (include/mitsuba/render/bsdf.h).
const uint BSDF_NULL = 1u;
const uint BSDF_DIFFUSE_REFLECTION = 2u;
const uint BSDF_DIFFUSE_TRANSMISSION = 4u;
const uint BSDF_GLOSSY_REFLECTION = 8u;
const uint BSDF_GLOSSY_TRANSMISSION = 16u;
const uint BSDF_DELTA_REFLECTION = 32u;
const uint BSDF_DELTA_TRANSMISSION = 64u;
const uint BSDF_DELTA = BSDF_NULL | BSDF_DELTA_REFLECTION | BSDF_DELTA_TRANSMISSION;
const uint BSDF_SMOOTH = BSDF_DIFFUSE_REFLECTION | BSDF_DIFFUSE_TRANSMISSION |
                         BSDF_GLOSSY_REFLECTION | BSDF_GLOSSY_TRANSMISSION;

// One sampled scattering direction. weight = f(wi, wo) |cos theta_o| / pdf for smooth lobes
// and the lobe's throughput factor for delta lobes; eta is the relative IOR crossed (1 for
// reflection); lobe is one BSDF_* flag. pdf = 0 and weight = 0 when sampling fails.
struct BsdfSample {
  vec3 wo;
  float pdf;
  vec3 weight;
  float eta;
  uint lobe;
  uint pad0;
  uint pad1;
  uint pad2;
};

INLINE BsdfSample bsdf_sample_failed() {
  BsdfSample s;
  s.wo = vec3(0.0f);
  s.pdf = 0.0f;
  s.weight = vec3(0.0f);
  s.eta = 1.0f;
  s.lobe = 0u;
  s.pad0 = 0u;
  s.pad1 = 0u;
  s.pad2 = 0u;
  return s;
}

INLINE BsdfSample bsdf_sample_make(vec3 wo, float pdf, vec3 weight, float eta, uint lobe) {
  BsdfSample s = bsdf_sample_failed();
  s.wo = wo;
  s.pdf = pdf;
  s.weight = weight;
  s.eta = eta;
  s.lobe = lobe;
  return s;
}

// A smooth-lobe sample from its density and value; rejects what a float cannot carry.
INLINE BsdfSample bsdf_sample_smooth(vec3 wo, float pdf, vec3 value, float eta, uint lobe) {
  vec3 weight = value / pdf;
  bool valid = pdf > 0.0f && pdf < FLOAT_MAX && !any(isnan(weight)) && !any(isinf(weight)) &&
               !any(isnan(wo));
  if (!valid) return bsdf_sample_failed();
  return bsdf_sample_make(wo, pdf, weight, eta, lobe);
}

// f(wi, wo) |cos theta_o| and the density of sampling wo, computed together where they share
// work (Mitsuba's BSDF::eval_pdf): the emitter sample's MIS needs both, and so does a sample.
struct BsdfEvalPdf {
  vec3 f;
  float pdf;
};

INLINE BsdfEvalPdf bsdf_eval_pdf_make(vec3 f, float pdf) {
  BsdfEvalPdf r;
  r.f = f;
  r.pdf = pdf;
  return r;
}

INLINE BsdfEvalPdf bsdf_eval_pdf_zero() { return bsdf_eval_pdf_make(vec3(0.0f), 0.0f); }

// A smooth-lobe sample from its value and density at wo.
INLINE BsdfSample bsdf_sample_smooth(vec3 wo, BsdfEvalPdf v, float eta, uint lobe) {
  return bsdf_sample_smooth(wo, v.pdf, v.f, eta, lobe);
}

// A scalar parameter (Mitsuba's Texture::eval_1): the loader stores scalar parameters already
// reduced as eval_1 reduces them (a bitmap's luminance, a constant color's channel mean), in
// every channel, so the first channel is the value.
INLINE float eval_textured_1(TexturedValue v, TexCoord uv) { return eval_textured(v, uv).x; }

// drjit::mulsign: x with the sign of s (s = 0 counts as positive).
INLINE float mulsign(float x, float s) { return s >= 0.0f ? x : -x; }

TR_NAMESPACE_END

#endif
