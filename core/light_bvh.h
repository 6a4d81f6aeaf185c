// Choosing an emitter by a light BVH (Conty Estevez & Kulla, "Importance Sampling of Many
// Lights with Adaptive Tree Splitting", HPG 2018; pbrt-v4 §12.6.3, BVHLightSampler). From the
// root, each interior node sends the choice to a child with probability proportional to the
// child's importance for the reference point, an upper-bound-shaped estimate of the light it
// sends there; this tree has up to LIGHT_BVH_WIDTH children a node (a binary tree collapsed,
// scenes/light_bvh_build.cpp), so a descent reads fewer, contiguous, groups of nodes. The
// probability of a given emitter is the product of those choices on the way from its leaf up to
// the root, recomputed with the same arithmetic (core/emitter.h's MIS densities depend on it).
#ifndef TWINRAY_CORE_LIGHT_BVH_H
#define TWINRAY_CORE_LIGHT_BVH_H

#include "core/scene_access.h"

TR_NAMESPACE_BEGIN

// cos(max(0, a - b)) and sin(max(0, a - b)) of angles given by their sines and cosines.
INLINE float cos_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  return cos_a > cos_b ? 1.0f : cos_a * cos_b + sin_a * sin_b;
}
INLINE float sin_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  return cos_a > cos_b ? 0.0f : sin_a * cos_b - cos_a * sin_b;
}

// Importance of a node for reference point p (pbrt-v4 LightBounds::Importance): its power over
// the squared distance to its centre (clamped to its radius, half its box's diagonal), times the
// cosine of the smallest angle between the direction from the node to p and the node's emission
// cone, once widened by the angle theta_b its sphere subtends from p. Zero only where nothing
// below the node can send light towards p.
INLINE float light_node_importance(IN(LightNode) n, vec3 p) {
  vec3 v = p - n.centre;
  float d2 = dot(v, v);
  float cos_theta_p = 1.0f;
  // Outside the sphere: the widened angle; inside it every direction is possible.
  if (d2 > n.radius * n.radius) {
    float inv_d = inversesqrt(d2);
    float cos_theta_w = dot(n.w, v) * inv_d;
    float sin_theta_w = safe_sqrt(1.0f - cos_theta_w * cos_theta_w);
    float sin_theta_b = n.radius * inv_d;
    float cos_theta_b = safe_sqrt(1.0f - sin_theta_b * sin_theta_b);
    float cos_theta_x = cos_sub_clamped(sin_theta_w, cos_theta_w, n.sin_theta_o, n.cos_theta_o);
    float sin_theta_x = sin_sub_clamped(sin_theta_w, cos_theta_w, n.sin_theta_o, n.cos_theta_o);
    cos_theta_p = cos_sub_clamped(sin_theta_x, cos_theta_x, sin_theta_b, cos_theta_b);
    if (cos_theta_p <= n.cos_theta_e) return 0.0f;
  }
  return n.phi * cos_theta_p / max(d2, n.radius);
}

// The importances of an interior node's children (zero past child_count) and their sum, added
// in the one order both the descent and the probability below use.
struct LightChildren {
  float importance[LIGHT_BVH_WIDTH];
  float total;  // 0 when not finite
};

INLINE LightChildren light_children(IN(LightNode) n, vec3 p) {
  LightChildren c;
  c.total = 0.0f;
  UNROLL for (uint k = 0u; k < LIGHT_BVH_WIDTH; ++k) {
    c.importance[k] =
        k < n.child_count ? light_node_importance(scene_light_node(n.first_child + k), p) : 0.0f;
    c.total += c.importance[k];
  }
  if (!(c.total < FLOAT_MAX)) c.total = 0.0f;
  return c;
}

// Descends from the root with u in [0, 1), rescaled at each choice. Returns the emitter of the
// leaf reached and its probability in pmf (0 and NO_INDEX when no emitter can light p).
INLINE uint light_bvh_sample(uint root, vec3 p, float u, OUT(float) pmf) {
  pmf = 0.0f;
  if (root == NO_INDEX) return NO_INDEX;
  LightNode n = scene_light_node(root);
  if (!(light_node_importance(n, p) > 0.0f)) return NO_INDEX;
  float prob = 1.0f;
  while (n.child_count != 0u) {
    LightChildren c = light_children(n, p);
    if (!(c.total > 0.0f)) return NO_INDEX;
    // The child of positive probability whose interval of the partial sums holds u (the last
    // such child when rounding leaves u past them all).
    uint chosen = 0u;
    float chosen_p = 0.0f, chosen_below = 0.0f, below = 0.0f;
    UNROLL for (uint k = 0u; k < LIGHT_BVH_WIDTH; ++k) {
      float p_k = c.importance[k] / c.total;
      if (p_k > 0.0f && u >= below) {
        chosen = k;
        chosen_p = p_k;
        chosen_below = below;
      }
      below += p_k;
    }
    u = clamp((u - chosen_below) / chosen_p, 0.0f, ONE_MINUS_EPSILON);
    prob *= chosen_p;
    n = scene_light_node(n.first_child + chosen);
  }
  pmf = prob;
  return n.emitter;
}

// The probability with which light_bvh_sample returns the emitter of leaf `leaf`
// (Emitter.light_leaf) from p.
INLINE float light_bvh_pmf(uint root, vec3 p, uint leaf) {
  if (root == NO_INDEX || leaf == NO_INDEX) return 0.0f;
  uint node = leaf;
  LightNode n = scene_light_node(node);
  float prob = 1.0f;
  while (node != root) {
    REF(LightNode) parent = scene_light_node(n.parent);
    LightChildren c = light_children(parent, p);
    float mine = 0.0f;
    UNROLL for (uint k = 0u; k < LIGHT_BVH_WIDTH; ++k) {
      if (parent.first_child + k == node) mine = c.importance[k];
    }
    prob *= c.total > 0.0f ? mine / c.total : 0.0f;
    node = n.parent;
    n = parent;
  }
  return light_node_importance(n, p) > 0.0f ? prob : 0.0f;
}

TR_NAMESPACE_END

#endif
