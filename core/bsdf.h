// The BSDF interface of the path tracer: flags, eval, pdf and sample of any Material, with
// Mitsuba 3 semantics. Each BSDF lives in core/bsdf/<name>.h; this file dispatches on
// Material.type and applies the two wrappers a Material can carry:
//   MATERIAL_TWOSIDED — Mitsuba `twosided` with one nested BSDF (src/bsdfs/twosided.cpp):
//     a direction wi below the surface is mirrored to the front side, wo keeps its side
//     relative to wi, sampled directions are mirrored back.
//   MATERIAL_MASKED — Mitsuba `mask` (src/bsdfs/mask.cpp): with opacity alpha, eval and pdf
//     are the nested ones times alpha; sampling passes straight through (null lobe, wo = -wi,
//     weight 1, pdf 1 - alpha) with probability 1 - alpha, else samples the nested BSDF with
//     u1 rescaled to [0, 1) (pdf times alpha, weight unchanged).
// The two wrappers commute, so their nesting order in the scene file does not matter.
// bsdf_leaf_* evaluate such a material; bsdf_tree_* also take Mitsuba `blendbsdf`
// (core/bsdf/blend.h), a mixture of other materials, possibly blends themselves; the public
// bsdf_* also take a `normalmap` around such a tree.
//
// uv is a TexCoord (core/texture.h); the public functions also take a plain vec2 uv.
//   bsdf_flags(m, uv)           lobes this material can produce (BSDF_* bits)
//   bsdf_eval(m, uv, wi, wo)    f(wi, wo) |cos theta_o|, zero for delta lobes
//   bsdf_pdf(m, uv, wi, wo)     solid-angle density of bsdf_sample returning wo (smooth lobes)
//   bsdf_surface_eval_pdf(g, m, uv, wi, wo)   both at once (Mitsuba's eval_pdf), at a surface
//   bsdf_sample(m, uv, wi, u1, u2)
//   bsdf_root(g, m, uv, wi), then bsdf_root_eval_pdf / bsdf_root_sample: the same calls at one
//     shading point, a root `normalmap`/`bumpmap` resolved once for all of them
#ifndef TWINRAY_CORE_BSDF_H
#define TWINRAY_CORE_BSDF_H

#include "core/bsdf/common.h"
#include "core/bsdf/conductor.h"
#include "core/bsdf/dielectric.h"
#include "core/bsdf/diffuse.h"
#include "core/bsdf/plastic.h"
#include "core/bsdf/pplastic.h"
#include "core/bsdf/principled.h"
#include "core/bsdf/roughconductor.h"
#include "core/bsdf/roughdielectric.h"
#include "core/bsdf/roughplastic.h"
#include "core/bsdf/thindielectric.h"

TR_NAMESPACE_BEGIN

INLINE uint bsdf_base_flags(IN(Material) m, TexCoord uv) {
  switch (m.type) {
    case BSDF_DIFFUSE:
      if (TR_HAS_BSDF(BSDF_DIFFUSE)) return diffuse_flags(m, uv);
      break;
    case BSDF_CONDUCTOR:
      if (TR_HAS_BSDF(BSDF_CONDUCTOR)) return conductor_flags(m, uv);
      break;
    case BSDF_ROUGHCONDUCTOR:
      if (TR_HAS_BSDF(BSDF_ROUGHCONDUCTOR)) return roughconductor_flags(m, uv);
      break;
    case BSDF_DIELECTRIC:
      if (TR_HAS_BSDF(BSDF_DIELECTRIC)) return dielectric_flags(m, uv);
      break;
    case BSDF_ROUGHDIELECTRIC:
      if (TR_HAS_BSDF(BSDF_ROUGHDIELECTRIC)) return roughdielectric_flags(m, uv);
      break;
    case BSDF_THINDIELECTRIC:
      if (TR_HAS_BSDF(BSDF_THINDIELECTRIC)) return thindielectric_flags(m, uv);
      break;
    case BSDF_PLASTIC:
      if (TR_HAS_BSDF(BSDF_PLASTIC)) return plastic_flags(m, uv);
      break;
    case BSDF_ROUGHPLASTIC:
      if (TR_HAS_BSDF(BSDF_ROUGHPLASTIC)) return roughplastic_flags(m, uv);
      break;
    case BSDF_PRINCIPLED:
      if (TR_HAS_BSDF(BSDF_PRINCIPLED)) return principled_flags(m, uv);
      break;
    case BSDF_PPLASTIC:
      if (TR_HAS_BSDF(BSDF_PPLASTIC)) return pplastic_flags(m, uv);
      break;
    default:
      break;
  }
  return 0u;
}

// Delta lobes have neither a density nor a value: only BSDFs with smooth lobes appear here.
INLINE BsdfEvalPdf bsdf_base_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  switch (m.type) {
    case BSDF_DIFFUSE:
      if (TR_HAS_BSDF(BSDF_DIFFUSE)) return diffuse_eval_pdf(m, uv, wi, wo);
      break;
    case BSDF_ROUGHCONDUCTOR:
      if (TR_HAS_BSDF(BSDF_ROUGHCONDUCTOR)) return roughconductor_eval_pdf(m, uv, wi, wo);
      break;
    case BSDF_ROUGHDIELECTRIC:
      if (TR_HAS_BSDF(BSDF_ROUGHDIELECTRIC)) return roughdielectric_eval_pdf(m, uv, wi, wo);
      break;
    case BSDF_PLASTIC:
      if (TR_HAS_BSDF(BSDF_PLASTIC)) return plastic_eval_pdf(m, uv, wi, wo);
      break;
    case BSDF_ROUGHPLASTIC:
      if (TR_HAS_BSDF(BSDF_ROUGHPLASTIC)) return roughplastic_eval_pdf(m, uv, wi, wo);
      break;
    case BSDF_PRINCIPLED:
      if (TR_HAS_BSDF(BSDF_PRINCIPLED)) return principled_eval_pdf(m, uv, wi, wo);
      break;
    case BSDF_PPLASTIC:
      if (TR_HAS_BSDF(BSDF_PPLASTIC)) return pplastic_eval_pdf(m, uv, wi, wo);
      break;
    default:
      break;
  }
  return bsdf_eval_pdf_zero();
}

INLINE BsdfSample bsdf_base_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  switch (m.type) {
    case BSDF_DIFFUSE:
      if (TR_HAS_BSDF(BSDF_DIFFUSE)) return diffuse_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_CONDUCTOR:
      if (TR_HAS_BSDF(BSDF_CONDUCTOR)) return conductor_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_ROUGHCONDUCTOR:
      if (TR_HAS_BSDF(BSDF_ROUGHCONDUCTOR)) return roughconductor_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_DIELECTRIC:
      if (TR_HAS_BSDF(BSDF_DIELECTRIC)) return dielectric_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_ROUGHDIELECTRIC:
      if (TR_HAS_BSDF(BSDF_ROUGHDIELECTRIC)) return roughdielectric_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_THINDIELECTRIC:
      if (TR_HAS_BSDF(BSDF_THINDIELECTRIC)) return thindielectric_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_PLASTIC:
      if (TR_HAS_BSDF(BSDF_PLASTIC)) return plastic_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_ROUGHPLASTIC:
      if (TR_HAS_BSDF(BSDF_ROUGHPLASTIC)) return roughplastic_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_PRINCIPLED:
      if (TR_HAS_BSDF(BSDF_PRINCIPLED)) return principled_sample(m, uv, wi, u1, u2);
      break;
    case BSDF_PPLASTIC:
      if (TR_HAS_BSDF(BSDF_PPLASTIC)) return pplastic_sample(m, uv, wi, u1, u2);
      break;
    default:
      break;
  }
  return bsdf_sample_failed();
}

// A leaf material with its textured parameters (and mask opacity) evaluated at uv; the BSDFs of
// core/bsdf/ read them as constants. GLSL inlines every call, so one lookup in a loop here
// instead of one per parameter read keeps a single copy of the texture code per leaf call. The
// roughplastic table slot holds a texture of its own, not a parameter, and is left as it is;
// flags are taken from the unevaluated material (a textured spec_trans transmits everywhere).
// A slot that no leaf material of the scene textures is skipped (TR_HAS_TEXTURED_SLOT: folded
// by the GPU pipeline's specialization, so its lookup code is not even compiled), and so is a
// material without textures.
INLINE Material material_at(IN(Material) stored, TexCoord uv) {
  Material m = stored;
  if ((m.flags & MATERIAL_TEXTURED) == 0u) return m;
  UNROLL for (uint k = 0u; k <= MATERIAL_PARAM_COUNT; ++k) {
    if (!TR_HAS_TEXTURED_SLOT(k)) continue;
    bool opacity = k == MATERIAL_PARAM_COUNT;
    if (!opacity && m.type == BSDF_ROUGHPLASTIC && k == ROUGHPLASTIC_TABLE) continue;
    TexturedValue v = opacity ? m.opacity : m.param[k];
    v.value = eval_textured(v, uv);
    v.texture = NO_INDEX;
    if (opacity)
      m.opacity = v;
    else
      m.param[k] = v;
  }
  return m;
}

// Mask opacity of a material_at, clipped to [0, 1] as Mitsuba's MaskBSDF::eval_opacity.
INLINE float bsdf_opacity(IN(Material) m) {
  if (TR_HAS_MATERIAL_FLAG(MATERIAL_MASKED) && (m.flags & MATERIAL_MASKED) != 0u)
    return clamp(m.opacity.value.x, 0.0f, 1.0f);
  return 1.0f;
}

INLINE uint bsdf_leaf_flags(IN(Material) m, TexCoord uv) {
  uint flags = bsdf_base_flags(m, uv);
  if (TR_HAS_MATERIAL_FLAG(MATERIAL_MASKED) && (m.flags & MATERIAL_MASKED) != 0u)
    flags |= BSDF_NULL;
  return flags;
}

INLINE BsdfEvalPdf bsdf_leaf_eval_pdf(IN(Material) stored, TexCoord uv, vec3 wi, vec3 wo) {
  Material m = material_at(stored, uv);
  if (TR_HAS_MATERIAL_FLAG(MATERIAL_TWOSIDED) && (m.flags & MATERIAL_TWOSIDED) != 0u) {
    wo.z = mulsign(wo.z, wi.z);
    wi.z = abs(wi.z);
  }
  BsdfEvalPdf v = bsdf_base_eval_pdf(m, uv, wi, wo);
  float opacity = bsdf_opacity(m);
  return bsdf_eval_pdf_make(v.f * opacity, v.pdf * opacity);
}

INLINE BsdfSample bsdf_leaf_sample(IN(Material) stored, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  Material m = material_at(stored, uv);
  float opacity = bsdf_opacity(m);
  if (u1 >= opacity) return bsdf_sample_make(-wi, 1.0f - opacity, vec3(1.0f), 1.0f, BSDF_NULL);
  u1 = u1 / opacity;
  float wi_z = wi.z;
  if (TR_HAS_MATERIAL_FLAG(MATERIAL_TWOSIDED) && (m.flags & MATERIAL_TWOSIDED) != 0u)
    wi.z = abs(wi.z);
  BsdfSample s = bsdf_base_sample(m, uv, wi, u1, u2);
  if (TR_HAS_MATERIAL_FLAG(MATERIAL_TWOSIDED) && (m.flags & MATERIAL_TWOSIDED) != 0u)
    s.wo.z = mulsign(s.wo.z, wi_z);
  s.pdf *= opacity;
  return s;
}

// Mitsuba's BSDF::eval_diffuse_reflectance (the `aov` integrator's albedo): the diffuse
// reflectance parameter where a BSDF has one (diffuse.cpp, plastic.cpp, roughplastic.cpp;
// principled.cpp: base_color), otherwise pi f(wi, n) cos = pi * eval at wo = the normal
// (src/render/bsdf.cpp). `twosided` mirrors wi to the front (twosided.cpp); `mask` returns the
// nested BSDF's (mask.cpp), without its opacity. The wrappers above a leaf:
// bsdf_diffuse_reflectance.
INLINE vec3 bsdf_leaf_diffuse_reflectance(IN(Material) stored, TexCoord uv, vec3 wi) {
  Material m = material_at(stored, uv);
  if (TR_HAS_MATERIAL_FLAG(MATERIAL_TWOSIDED) && (m.flags & MATERIAL_TWOSIDED) != 0u)
    wi.z = abs(wi.z);
  switch (m.type) {
    case BSDF_DIFFUSE:
      if (TR_HAS_BSDF(BSDF_DIFFUSE)) return m.param[DIFFUSE_REFLECTANCE].value;
      break;
    case BSDF_PLASTIC:
    case BSDF_ROUGHPLASTIC:
      if (TR_HAS_BSDF(BSDF_PLASTIC) || TR_HAS_BSDF(BSDF_ROUGHPLASTIC))
        return m.param[PLASTIC_DIFFUSE_REFLECTANCE].value;
      break;
    case BSDF_PRINCIPLED:
      if (TR_HAS_BSDF(BSDF_PRINCIPLED)) return m.param[PRINCIPLED_BASE_COLOR].value;
      break;
    default:
      break;
  }
  return PI * bsdf_base_eval_pdf(m, uv, wi, vec3(0.0f, 0.0f, 1.0f)).f;
}

TR_NAMESPACE_END

#include "core/bsdf/blend.h"
#include "core/bsdf/bumpmap.h"
#include "core/bsdf/normalmap.h"

TR_NAMESPACE_BEGIN

INLINE uint bsdf_tree_flags(IN(Material) m, TexCoord uv) {
  if (TR_HAS_BSDF(BSDF_BLEND) && m.type == BSDF_BLEND) return m.lobes;
  return bsdf_leaf_flags(m, uv);
}

// Mitsuba's blendbsdf m_flags, the union of its children's flags whatever the weight, set by its
// constructor: a blend's Material.lobes, set when the blend is built. No BSDF's flags depend on
// the position.
INLINE uint blend_lobes(IN(Material) child_0, IN(Material) child_1) {
  TexCoord uv = tex_coord(vec2(0.0f));
  return bsdf_tree_flags(child_0, uv) | bsdf_tree_flags(child_1, uv);
}

INLINE BsdfEvalPdf bsdf_tree_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  if (TR_HAS_BSDF(BSDF_BLEND) && m.type == BSDF_BLEND) return blend_eval_pdf(m, uv, wi, wo);
  return bsdf_leaf_eval_pdf(m, uv, wi, wo);
}

INLINE BsdfSample bsdf_tree_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  if (TR_HAS_BSDF(BSDF_BLEND) && m.type == BSDF_BLEND) return blend_sample(m, uv, wi, u1, u2);
  return bsdf_leaf_sample(m, uv, wi, u1, u2);
}

// The public interface: a `normalmap` (core/bsdf/normalmap.h) or `bumpmap`
// (core/bsdf/bumpmap.h) at the root perturbs wi and wo (after its own `twosided`, if any) and
// scales the tree below it. Both keep their child and options in the same slots. The
// bsdf_surface_* functions take the surface's differential geometry (bumpmap needs it); the
// plain ones assume bsdf_surface_flat().
INLINE bool bsdf_is_normalmap(IN(Material) m) {
  return TR_HAS_BSDF(BSDF_NORMALMAP) && m.type == BSDF_NORMALMAP;
}

INLINE bool bsdf_is_bumpmap(IN(Material) m) {
  return TR_HAS_BSDF(BSDF_BUMPMAP) && m.type == BSDF_BUMPMAP;
}

INLINE bool bsdf_is_perturbed(IN(Material) m) { return bsdf_is_normalmap(m) || bsdf_is_bumpmap(m); }

INLINE Frame bsdf_perturbed_frame(IN(Material) m, IN(BsdfSurface) g, TexCoord uv, vec3 wi) {
  if (bsdf_is_bumpmap(m)) return bumpmap_frame(m, g, uv, wi);
  return normalmap_frame(m, uv, wi);
}

INLINE uint bsdf_flags(Material m, TexCoord uv) {
  if (bsdf_is_perturbed(m)) m = scene_material(normalmap_child(m));
  return bsdf_tree_flags(m, uv);
}

// A root `normalmap` or `bumpmap` resolved at a shading point for incident direction wi: its
// perturbed frame (relative to the shading frame) and options, which a vertex's two BSDF calls
// (the light sample's evaluation, the BSDF sample) share, so its texture lookup and frame are
// computed once. perturbed 0: no such wrapper, the frame is unread.
struct BsdfRoot {
  Frame frame;
  uint perturbed;
  uint twosided;   // the wrapper's own `twosided`
  uint shadowing;  // use_shadowing_function
};

INLINE BsdfRoot bsdf_root(IN(BsdfSurface) g, IN(Material) m, TexCoord uv, vec3 wi) {
  BsdfRoot r;
  r.frame = frame_from_normal(vec3(0.0f, 0.0f, 1.0f));
  r.perturbed = bsdf_is_perturbed(m) ? 1u : 0u;
  r.twosided = r.perturbed != 0u && (m.flags & MATERIAL_TWOSIDED) != 0u ? 1u : 0u;
  r.shadowing = r.perturbed != 0u && normalmap_shadowing(m) ? 1u : 0u;
  if (r.perturbed != 0u) {
    if (r.twosided != 0u) wi.z = abs(wi.z);
    r.frame = bsdf_perturbed_frame(m, g, uv, wi);
  }
  return r;
}

// eval and pdf of the material `tree` below root r (the wrapper's child, or the material itself
// when r is not perturbed). The shadow terminator scales the value, not the density.
INLINE BsdfEvalPdf bsdf_root_eval_pdf(IN(BsdfRoot) r, IN(Material) tree, TexCoord uv, vec3 wi,
                                      vec3 wo) {
  float scale = 1.0f;
  if (r.perturbed != 0u) {
    if (r.twosided != 0u) {
      wo.z = mulsign(wo.z, wi.z);
      wi.z = abs(wi.z);
    }
    vec3 wo_perturbed = frame_to_local(r.frame, wo);
    if (!(wo.z * wo_perturbed.z > 0.0f)) return bsdf_eval_pdf_zero();
    if (r.shadowing != 0u) scale = normalmap_shadow_terminator(r.frame.n, wo);
    wi = frame_to_local(r.frame, wi);
    wo = wo_perturbed;
  }
  BsdfEvalPdf v = bsdf_tree_eval_pdf(tree, uv, wi, wo);
  v.f *= scale;
  return v;
}

INLINE BsdfSample bsdf_root_sample(IN(BsdfRoot) r, IN(Material) tree, TexCoord uv, vec3 wi,
                                   float u1, vec2 u2) {
  float wi_z = wi.z;
  if (r.twosided != 0u) wi.z = abs(wi.z);
  if (r.perturbed != 0u) wi = frame_to_local(r.frame, wi);
  BsdfSample s = bsdf_tree_sample(tree, uv, wi, u1, u2);
  if (r.perturbed != 0u) {
    vec3 wo = frame_to_world(r.frame, s.wo);
    if (!(s.wo.z * wo.z > 0.0f) || all(equal(s.weight, vec3(0.0f)))) return bsdf_sample_failed();
    if (r.shadowing != 0u) s.weight *= normalmap_shadow_terminator(r.frame.n, wo);
    s.wo = wo;
    if (r.twosided != 0u) s.wo.z = mulsign(s.wo.z, wi_z);
  }
  return s;
}

INLINE BsdfEvalPdf bsdf_surface_eval_pdf(IN(BsdfSurface) g, Material m, TexCoord uv, vec3 wi,
                                         vec3 wo) {
  BsdfRoot r = bsdf_root(g, m, uv, wi);
  if (r.perturbed != 0u) m = scene_material(normalmap_child(m));
  return bsdf_root_eval_pdf(r, m, uv, wi, wo);
}

INLINE BsdfSample bsdf_surface_sample(IN(BsdfSurface) g, Material m, TexCoord uv, vec3 wi, float u1,
                                      vec2 u2) {
  BsdfRoot r = bsdf_root(g, m, uv, wi);
  if (r.perturbed != 0u) m = scene_material(normalmap_child(m));
  return bsdf_root_sample(r, m, uv, wi, u1, u2);
}

// Mitsuba's eval_diffuse_reflectance through the wrappers: normalmap.cpp and bumpmap.cpp return
// the nested BSDF's at the unperturbed interaction, blendbsdf.cpp the weighted mix of its
// children's (core/bsdf/blend.h).
INLINE vec3 bsdf_diffuse_reflectance(Material m, TexCoord uv, vec3 wi) {
  if (bsdf_is_perturbed(m)) {
    if ((m.flags & MATERIAL_TWOSIDED) != 0u) wi.z = abs(wi.z);
    m = scene_material(normalmap_child(m));
  }
  if (TR_HAS_BSDF(BSDF_BLEND) && m.type == BSDF_BLEND) return blend_diffuse_reflectance(m, uv, wi);
  return bsdf_leaf_diffuse_reflectance(m, uv, wi);
}

INLINE vec3 bsdf_eval(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  return bsdf_surface_eval_pdf(bsdf_surface_flat(), m, uv, wi, wo).f;
}

INLINE float bsdf_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  return bsdf_surface_eval_pdf(bsdf_surface_flat(), m, uv, wi, wo).pdf;
}

INLINE BsdfSample bsdf_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  return bsdf_surface_sample(bsdf_surface_flat(), m, uv, wi, u1, u2);
}

// The same at a point known only by its uv (no mesh attributes).
INLINE uint bsdf_flags(IN(Material) m, vec2 uv) { return bsdf_flags(m, tex_coord(uv)); }

INLINE vec3 bsdf_eval(IN(Material) m, vec2 uv, vec3 wi, vec3 wo) {
  return bsdf_eval(m, tex_coord(uv), wi, wo);
}

INLINE float bsdf_pdf(IN(Material) m, vec2 uv, vec3 wi, vec3 wo) {
  return bsdf_pdf(m, tex_coord(uv), wi, wo);
}

INLINE BsdfSample bsdf_sample(IN(Material) m, vec2 uv, vec3 wi, float u1, vec2 u2) {
  return bsdf_sample(m, tex_coord(uv), wi, u1, u2);
}

TR_NAMESPACE_END

#endif
