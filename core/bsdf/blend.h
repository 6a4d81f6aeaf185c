// Mitsuba 3 `blendbsdf` (src/bsdfs/blendbsdf.cpp): the mixture
//   f = (1 - w) f_0 + w f_1,   pdf = (1 - w) pdf_0 + w pdf_1,   w = clip(weight.eval_1, 0, 1).
// sample() picks child 1 when u1 <= w (u1 / w rescaled), child 0 otherwise ((u1 - w) / (1 - w)),
// samples it, and returns the mixture at the sampled wo: the chosen child contributes its own
// sample's value (weight * pdf) and pdf, the other child its eval and pdf there; the returned
// weight is value / pdf over the mixture. The sampled lobe and eta are the chosen child's.
// Two departures from Mitsuba 3.8, where it is wrong: a sampled delta lobe (or a mask's null
// lobe) keeps its weight and gets pdf w_chosen pdf_child, while Mitsuba also adds the other
// child's smooth eval and pdf at that single direction (an atom mixed with a density: its
// chi-square mass exceeds 1 and renders are biased); and at u1 = w = 0 Mitsuba takes child 1
// and divides by zero, here child 0 is taken.
//
// Children are materials referred to by index (BLEND_BSDF_0/1), so blends nest; GLSL has no
// recursion, so the tree is walked by loops (blend_leaf, blend_next). Unrolling Mitsuba's recursive
// mixture, every leaf (a non-blend material) j enters with the product W_j of the weights on
// its path; the sampled leaf L contributes W_L (value_L, pdf_L), every other leaf
// W_j (eval_j(wo), pdf_j(wo)). A `twosided` on a blend applies to every leaf below it (it is
// idempotent, so the flag is inherited); the loader refuses a `mask` around a blend.
#ifndef TWINRAY_CORE_BSDF_BLEND_H
#define TWINRAY_CORE_BSDF_BLEND_H

#include "core/bsdf/common.h"
#include "core/material_slots.h"
#include "core/scene_access.h"

// Included by core/bsdf.h after bsdf_leaf_flags/eval_pdf/sample, which evaluate one non-blend
// material with its `twosided` and `mask` wrappers.

TR_NAMESPACE_BEGIN

INLINE float blend_weight(IN(Material) m, TexCoord uv) {
  return clamp(eval_textured_1(m.param[BLEND_WEIGHT], uv), 0.0f, 1.0f);
}

INLINE uint blend_child(IN(Material) m, uint which) {
  return uint(m.param[which == 0u ? BLEND_BSDF_0 : BLEND_BSDF_1].value.x);
}

// A node of the tree is named by its path code: 1 for the root, 2 code + k for its child k. The
// walks visit the leaves depth first, child 1 before child 0, without a stack: a leaf is found
// from the root by its code, and the next code follows from the last (no array, so a GPU keeps
// the walk in registers).
//
// The leaf at `path` or, when that node is a blend, below it through child 1 at each level
// (path is extended to the leaf's code). Its weight is the product of the weights met from the
// root, its flags carry the `twosided` of any blend above it.
INLINE Material blend_leaf(IN(Material) root, TexCoord uv, INOUT(uint) path, OUT(float) weight) {
  Material node = root;
  uint twosided = 0u;
  int level = findMSB(path);  // bits of path below its leading 1 still to follow
  weight = 1.0f;
  for (uint depth = 0u; depth < BLEND_MAX_DEPTH && node.type == BSDF_BLEND; ++depth) {
    uint child = 1u;
    if (level > 0) {
      level -= 1;
      child = (path >> uint(level)) & 1u;
    } else {
      path = 2u * path + 1u;
    }
    float w = blend_weight(node, uv);
    weight *= child == 1u ? w : 1.0f - w;
    twosided |= node.flags & MATERIAL_TWOSIDED;
    node = scene_material(blend_child(node, child));
  }
  node.flags |= twosided;
  return node;
}

// The code of the walk's next node after the leaf at `path` (climb over child-0 steps, then take
// the child 0 beside the last child 1), or 1 (the root) when that leaf was the last.
INLINE uint blend_next(uint path) {
  while ((path & 1u) == 0u) path >>= 1u;
  return path == 1u ? 1u : path - 1u;
}

// blendbsdf.cpp's eval_diffuse_reflectance: (1 - w) first + w second, recursively.
INLINE vec3 blend_diffuse_reflectance(IN(Material) m, TexCoord uv, vec3 wi) {
  vec3 value = vec3(0.0f);
  uint path = 1u;
  do {
    float weight;
    Material leaf = blend_leaf(m, uv, path, weight);
    if (weight > 0.0f) value += weight * bsdf_leaf_diffuse_reflectance(leaf, uv, wi);
    path = blend_next(path);
  } while (path != 1u);
  return value;
}

INLINE BsdfEvalPdf blend_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  BsdfEvalPdf sum = bsdf_eval_pdf_zero();
  uint path = 1u;
  do {
    float weight;
    Material leaf = blend_leaf(m, uv, path, weight);
    if (weight > 0.0f) {
      BsdfEvalPdf v = bsdf_leaf_eval_pdf(leaf, uv, wi, wo);
      sum.f += weight * v.f;
      sum.pdf += weight * v.pdf;
    }
    path = blend_next(path);
  } while (path != 1u);
  return sum;
}

INLINE BsdfSample blend_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  // Descend to one leaf, reusing u1 at each blend (child 1 when u1 <= w, as Mitsuba; the
  // rescaled u1 stays below 1 so that leaves see a sample in [0, 1)).
  Material node = m;
  float chosen_weight = 1.0f;
  uint chosen_path = 1u;
  uint inherited = 0u;
  for (uint depth = 0u; depth < BLEND_MAX_DEPTH && node.type == BSDF_BLEND; ++depth) {
    float w = blend_weight(node, uv);
    inherited |= node.flags & MATERIAL_TWOSIDED;
    uint child = (u1 <= w && w > 0.0f) ? 1u : 0u;
    if (child == 1u) {
      u1 = u1 / w;
      chosen_weight *= w;
    } else {
      u1 = (u1 - w) / (1.0f - w);
      chosen_weight *= 1.0f - w;
    }
    u1 = min(u1, ONE_MINUS_EPSILON);
    chosen_path = 2u * chosen_path + child;
    node = scene_material(blend_child(node, child));
  }
  node.flags |= inherited;
  BsdfSample s = bsdf_leaf_sample(node, uv, wi, u1, u2);
  if (!(s.pdf > 0.0f)) return bsdf_sample_failed();

  // A delta lobe is an atom of the mixture: the other leaves' densities do not mix into it.
  if ((s.lobe & BSDF_DELTA) != 0u) {
    s.pdf *= chosen_weight;
    return s;
  }
  vec3 value = chosen_weight * s.weight * s.pdf;
  float pdf = chosen_weight * s.pdf;
  uint path = 1u;
  do {
    float weight;
    Material leaf = blend_leaf(m, uv, path, weight);
    if (path != chosen_path && weight > 0.0f) {
      BsdfEvalPdf v = bsdf_leaf_eval_pdf(leaf, uv, wi, s.wo);
      value += weight * v.f;
      pdf += weight * v.pdf;
    }
    path = blend_next(path);
  } while (path != 1u);
  s.pdf = pdf;
  s.weight = value / pdf;
  return s;
}

TR_NAMESPACE_END

#endif
