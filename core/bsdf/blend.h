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

// Both slots read at constant indices: a record's array member indexed by a variable is copied
// whole into a GPU's local memory first.
INLINE uint blend_child(IN(Material) m, uint which) {
  uint child_0 = uint(m.param[BLEND_BSDF_0].value.x);
  uint child_1 = uint(m.param[BLEND_BSDF_1].value.x);
  return which == 0u ? child_0 : child_1;
}

// A node of the tree is named by its path code: 1 for the root, 2 code + k for its child k. The
// walks visit the leaves depth first, child 1 before child 0, without a stack: a leaf is found
// from the root by its code, and the next code follows from the last. The loops carry material
// indices, not records: a GPU then keeps a walk in registers.
//
// One level down from `node`, a blend of weight w, to its child `child`: the path's weight and
// inherited `twosided` updated, the child's material index returned.
INLINE uint blend_step(IN(Material) node, float w, uint child, INOUT(float) weight,
                       INOUT(uint) twosided) {
  weight *= child == 1u ? w : 1.0f - w;
  twosided |= node.flags & MATERIAL_TWOSIDED;
  return blend_child(node, child);
}

// The child to take at the next level: path's next bit (level counts the bits left below its
// leading 1) or, past its end, child 1, path extended by it.
INLINE uint blend_path_child(INOUT(uint) path, INOUT(int) level) {
  if (level > 0) {
    level -= 1;
    return (path >> uint(level)) & 1u;
  }
  path = 2u * path + 1u;
  return 1u;
}

// The leaf at `path` below the blend `root` (of weight w_root, evaluated once per walk) or, when
// that node is a blend, below it through child 1 at each level (path is extended to the leaf's
// code): its material index, the product of the weights met from the root, and the `twosided`
// of any blend above it. The weights of nested blends are evaluated again for each leaf below
// them: the price of keeping no stack.
INLINE uint blend_leaf(IN(Material) root, float w_root, TexCoord uv, INOUT(uint) path,
                       OUT(float) weight, OUT(uint) twosided) {
  int level = findMSB(path);
  weight = 1.0f;
  twosided = 0u;
  uint index = blend_step(root, w_root, blend_path_child(path, level), weight, twosided);
  for (uint depth = 1u; depth < BLEND_MAX_DEPTH && scene_material(index).type == BSDF_BLEND;
       ++depth) {
    REF(Material) node = scene_material(index);
    index =
        blend_step(node, blend_weight(node, uv), blend_path_child(path, level), weight, twosided);
  }
  return index;
}

// The leaf's record with the `twosided` of the blends above it.
INLINE Material blend_leaf_material(uint index, uint twosided) {
  Material leaf = scene_material(index);
  leaf.flags |= twosided;
  return leaf;
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
  float w_root = blend_weight(m, uv);
  uint path = 1u;
  do {
    float weight;
    uint twosided;
    uint leaf = blend_leaf(m, w_root, uv, path, weight, twosided);
    if (weight > 0.0f)
      value += weight * bsdf_leaf_diffuse_reflectance(blend_leaf_material(leaf, twosided), uv, wi);
    path = blend_next(path);
  } while (path != 1u);
  return value;
}

INLINE BsdfEvalPdf blend_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  BsdfEvalPdf sum = bsdf_eval_pdf_zero();
  float w_root = blend_weight(m, uv);
  uint path = 1u;
  do {
    float weight;
    uint twosided;
    uint leaf = blend_leaf(m, w_root, uv, path, weight, twosided);
    if (weight > 0.0f) {
      BsdfEvalPdf v = bsdf_leaf_eval_pdf(blend_leaf_material(leaf, twosided), uv, wi, wo);
      sum.f += weight * v.f;
      sum.pdf += weight * v.pdf;
    }
    path = blend_next(path);
  } while (path != 1u);
  return sum;
}

// One level of blend_sample's descent: child 1 when u1 <= w (as Mitsuba), u1 rescaled to the
// chosen child's share and kept below 1 so that leaves see a sample in [0, 1).
INLINE uint blend_choose(IN(Material) node, float w, INOUT(float) u1, INOUT(float) weight,
                         INOUT(uint) path, INOUT(uint) twosided) {
  uint child = (u1 <= w && w > 0.0f) ? 1u : 0u;
  u1 = min(child == 1u ? u1 / w : (u1 - w) / (1.0f - w), ONE_MINUS_EPSILON);
  path = 2u * path + child;
  return blend_step(node, w, child, weight, twosided);
}

INLINE BsdfSample blend_sample(IN(Material) m, TexCoord uv, vec3 wi, float u1, vec2 u2) {
  // Descend to one leaf, reusing u1 at each blend.
  float chosen_weight = 1.0f;
  uint chosen_path = 1u;
  uint chosen_twosided = 0u;
  float w_root = blend_weight(m, uv);
  uint chosen = blend_choose(m, w_root, u1, chosen_weight, chosen_path, chosen_twosided);
  for (uint depth = 1u; depth < BLEND_MAX_DEPTH && scene_material(chosen).type == BSDF_BLEND;
       ++depth) {
    REF(Material) node = scene_material(chosen);
    chosen =
        blend_choose(node, blend_weight(node, uv), u1, chosen_weight, chosen_path, chosen_twosided);
  }
  BsdfSample s = bsdf_leaf_sample(blend_leaf_material(chosen, chosen_twosided), uv, wi, u1, u2);
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
    uint twosided;
    uint leaf = blend_leaf(m, w_root, uv, path, weight, twosided);
    if (path != chosen_path && weight > 0.0f) {
      BsdfEvalPdf v = bsdf_leaf_eval_pdf(blend_leaf_material(leaf, twosided), uv, wi, s.wo);
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
