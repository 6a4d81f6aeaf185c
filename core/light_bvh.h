// Choosing an emitter by a light BVH (Conty Estevez & Kulla, "Importance Sampling of Many
// Lights with Adaptive Tree Splitting", HPG 2018; pbrt-v4 §12.6.3, BVHLightSampler). From the
// root, each interior node sends the choice to a child with probability proportional to the
// child's importance for the reference point, an upper-bound-shaped estimate of the light it
// sends there. The probability of a given emitter is the product of those choices on the way
// from its leaf up to the root, recomputed with the same arithmetic (core/emitter.h's MIS
// densities depend on it).
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

// The probability of the child `first` (child0 when true) at an interior node, from the two
// children's importances; zero when neither can light p.
INLINE float light_child_probability(float importance0, float importance1, bool first) {
  float total = importance0 + importance1;
  if (!(total > 0.0f) || !(total < FLOAT_MAX)) return 0.0f;
  return (first ? importance0 : importance1) / total;
}

// Descends from the root with u in [0, 1), rescaled at each choice. Returns the emitter of the
// leaf reached and its probability in pmf (0 and NO_INDEX when no emitter can light p).
INLINE uint light_bvh_sample(uint root, vec3 p, float u, OUT(float) pmf) {
  pmf = 0.0f;
  if (root == NO_INDEX) return NO_INDEX;
  LightNode n = scene_light_node(root);
  if (!(light_node_importance(n, p) > 0.0f)) return NO_INDEX;
  float prob = 1.0f;
  while (n.child0 != NO_INDEX) {
    REF(LightNode) c0 = scene_light_node(n.child0);
    REF(LightNode) c1 = scene_light_node(n.child1);
    float i0 = light_node_importance(c0, p);
    float i1 = light_node_importance(c1, p);
    float p0 = light_child_probability(i0, i1, true);
    float p1 = light_child_probability(i0, i1, false);
    if (!(p0 + p1 > 0.0f)) return NO_INDEX;
    if (u < p0) {
      n = c0;
      u = min(u / p0, ONE_MINUS_EPSILON);
      prob *= p0;
    } else {
      n = c1;
      u = min((u - p0) / p1, ONE_MINUS_EPSILON);
      prob *= p1;
    }
  }
  pmf = prob;
  return n.child1;
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
    float i0 = light_node_importance(scene_light_node(parent.child0), p);
    float i1 = light_node_importance(scene_light_node(parent.child1), p);
    prob *= light_child_probability(i0, i1, parent.child0 == node);
    node = n.parent;
    n = parent;
  }
  return light_node_importance(n, p) > 0.0f ? prob : 0.0f;
}

TR_NAMESPACE_END

#endif
