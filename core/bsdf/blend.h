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
// recursion, so the tree is walked with an explicit stack. Unrolling Mitsuba's recursive
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

// A tree of at most BLEND_MAX_DEPTH levels of blends (the loader enforces it) keeps the
// depth-first walk within BLEND_STACK_SIZE = BLEND_MAX_DEPTH + 1 entries.
const uint BLEND_STACK_SIZE = BLEND_MAX_DEPTH + 1u;

INLINE float blend_weight(IN(Material) m, TexCoord uv) {
  return clamp(eval_textured_1(m.param[BLEND_WEIGHT], uv), 0.0f, 1.0f);
}

INLINE uint blend_child(IN(Material) m, uint which) {
  return uint(m.param[which == 0u ? BLEND_BSDF_0 : BLEND_BSDF_1].value.x);
}

// The depth-first walk: a node's material index, the product of the blend weights on its path,
// its path code (1 for the root, 2 code + child below), and the inherited `twosided` flag.
struct BlendStack {
  uint node[BLEND_STACK_SIZE];
  float weight[BLEND_STACK_SIZE];
  uint path[BLEND_STACK_SIZE];
  uint flags[BLEND_STACK_SIZE];
  uint size;
};

INLINE void blend_push(INOUT(BlendStack) st, uint node, float weight, uint path, uint flags) {
  st.node[st.size] = node;
  st.weight[st.size] = weight;
  st.path[st.size] = path;
  st.flags[st.size] = flags;
  st.size += 1u;
}

INLINE void blend_push_children(INOUT(BlendStack) st, IN(Material) blend, TexCoord uv, float weight,
                                uint path, uint inherited_flags) {
  // The loader bounds the nesting depth (BLEND_MAX_DEPTH), so the stack never overflows.
  if (st.size + 2u > BLEND_STACK_SIZE) return;
  float w = blend_weight(blend, uv);
  uint flags = inherited_flags | (blend.flags & MATERIAL_TWOSIDED);
  blend_push(st, blend_child(blend, 0u), weight * (1.0f - w), 2u * path, flags);
  blend_push(st, blend_child(blend, 1u), weight * w, 2u * path + 1u, flags);
}

INLINE BlendStack blend_walk(IN(Material) root, TexCoord uv) {
  BlendStack st;
  st.size = 0u;
  blend_push_children(st, root, uv, 1.0f, 1u, 0u);
  return st;
}

// Pops entries until a leaf comes up, expanding blends on the way; false when the walk is over.
INLINE bool blend_next_leaf(INOUT(BlendStack) st, TexCoord uv, OUT(Material) leaf,
                            OUT(float) weight, OUT(uint) path) {
  while (st.size > 0u) {
    st.size -= 1u;
    Material m = scene_material(st.node[st.size]);
    m.flags |= st.flags[st.size];
    if (m.type == BSDF_BLEND) {
      blend_push_children(st, m, uv, st.weight[st.size], st.path[st.size], st.flags[st.size]);
      continue;
    }
    leaf = m;
    weight = st.weight[st.size];
    path = st.path[st.size];
    return true;
  }
  return false;
}

// Mitsuba's m_flags: the union of the children's flags, whatever the weight.
INLINE uint blend_flags(IN(Material) m, TexCoord uv) {
  BlendStack st = blend_walk(m, uv);
  Material leaf;
  float weight;
  uint path;
  uint flags = 0u;
  while (blend_next_leaf(st, uv, leaf, weight, path)) flags |= bsdf_leaf_flags(leaf, uv);
  return flags;
}

// blendbsdf.cpp's eval_diffuse_reflectance: (1 - w) first + w second, recursively.
INLINE vec3 blend_diffuse_reflectance(IN(Material) m, TexCoord uv, vec3 wi) {
  BlendStack st = blend_walk(m, uv);
  Material leaf;
  float weight;
  uint path;
  vec3 value = vec3(0.0f);
  while (blend_next_leaf(st, uv, leaf, weight, path))
    if (weight > 0.0f) value += weight * bsdf_leaf_diffuse_reflectance(leaf, uv, wi);
  return value;
}

INLINE BsdfEvalPdf blend_eval_pdf(IN(Material) m, TexCoord uv, vec3 wi, vec3 wo) {
  BlendStack st = blend_walk(m, uv);
  Material leaf;
  float weight;
  uint path;
  BsdfEvalPdf sum = bsdf_eval_pdf_zero();
  while (blend_next_leaf(st, uv, leaf, weight, path)) {
    if (!(weight > 0.0f)) continue;
    BsdfEvalPdf v = bsdf_leaf_eval_pdf(leaf, uv, wi, wo);
    sum.f += weight * v.f;
    sum.pdf += weight * v.pdf;
  }
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
  BlendStack st = blend_walk(m, uv);
  Material leaf;
  float weight;
  uint path;
  while (blend_next_leaf(st, uv, leaf, weight, path)) {
    if (path == chosen_path || !(weight > 0.0f)) continue;
    BsdfEvalPdf v = bsdf_leaf_eval_pdf(leaf, uv, wi, s.wo);
    value += weight * v.f;
    pdf += weight * v.pdf;
  }
  s.pdf = pdf;
  s.weight = value / pdf;
  return s;
}

TR_NAMESPACE_END

#endif
