#include "scenes/light_bounds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/shapes/bounds.h"

namespace tr {

namespace {

constexpr double kPi = 3.14159265358979323846;

double max_abs(const vec3& c) {
  return std::max({std::abs(double(c.x)), std::abs(double(c.y)), std::abs(double(c.z))});
}

glm::dmat3 rows_to_matrix(const vec4 rows[3]) {
  glm::dmat3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[c][r] = double(rows[r][c]);
  return m;
}

// Whether the linear map keeps angles (a rotation, reflection and uniform scale), so that a
// cone in its domain maps to a cone of the same angle.
bool keeps_angles(const glm::dmat3& m) {
  glm::dmat3 g = glm::transpose(m) * m;
  double s = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (std::abs(g[c][r] - (r == c ? s : 0.0)) > 1e-5 * s) return false;
  return s > 0.0;
}

// The mean over a texture of its largest channel: what a texture scales an emitter's power by.
double texture_mean(const SceneBuffers& b, uint index) {
  if (index == NO_INDEX) return 1.0;
  const Texture& t = b.textures[index];
  if (t.type == TEXTURE_CHECKERBOARD)
    return 0.5 * (max_abs(vec3(t.color0)) + max_abs(vec3(t.color1)));
  if (t.type != TEXTURE_BITMAP)
    throw std::logic_error("emitter bounds: an emitter texture is a bitmap or checkerboard");
  double sum = 0.0;
  const size_t n = size_t(t.width) * t.height;
  for (size_t i = 0; i < n; ++i) sum += max_abs(vec3(b.texels[t.texel_offset + i]));
  return sum / double(n);
}

// The mean over the sphere of an envmap's largest channel (rows top to bottom span theta from
// 0 to pi, core/emitters/envmap.h): texels weighted by sin(theta).
double envmap_mean(const SceneBuffers& b, const Emitter& e) {
  const Texture& t = b.textures[e.texture];
  double sum = 0.0, weight = 0.0;
  for (uint y = 0; y < t.height; ++y) {
    double w = std::sin(kPi * (y + 0.5) / t.height);
    for (uint x = 0; x < t.width; ++x)
      sum += w * max_abs(vec3(b.texels[t.texel_offset + size_t(y) * t.width + x]));
    weight += w * t.width;
  }
  return double(e.scale) * sum / weight;
}

void grow(LightBounds& l, const glm::dvec3& p) {
  l.lo = glm::min(l.lo, p);
  l.hi = glm::max(l.hi, p);
}

// An analytic shape's box (core/shapes/bounds.h), padded for the float transform's rounding.
void analytic_box(LightBounds& l, const Shape& s) {
  vec3 lo, hi;
  analytic_shape_bounds(s, lo, hi);
  const glm::dvec3 pad = 1e-5 * glm::dvec3(hi - lo) + 1e-6;
  grow(l, glm::dvec3(lo) - pad);
  grow(l, glm::dvec3(hi) + pad);
}

// Area emitters: the shape's box and the cone of its normals as the emitter samples and
// evaluates them (shading normals where the mesh has them, flip_normals applied). A textured
// radiance counts with its mean over the texture, the mean over the surface where the uvs cover
// the texture once (phi only weighs the choice: it is positive whenever any texel emits).
void area_bounds(const SceneBuffers& b, const Emitter& e, LightBounds& l) {
  const Shape& s = b.shapes[e.shape];
  l.phi = kPi * max_abs(e.radiance) * double(s.area) * texture_mean(b, e.texture);
  l.cos_theta_e = 0.0;
  const double flip = (s.flags & SHAPE_FLIP_NORMALS) != 0u ? -1.0 : 1.0;
  l.lo = glm::dvec3(INFINITY);
  l.hi = glm::dvec3(-INFINITY);
  if (s.type == SHAPE_MESH) {
    const bool shading = (s.flags & SHAPE_HAS_NORMALS) != 0u;
    for (uint t = 0; t < s.triangle_count; ++t) {
      glm::dvec3 p[3];
      for (uint k = 0; k < 3; ++k) {
        uint v = s.first_vertex + b.indices[s.first_index + 3 * t + k];
        p[k] = glm::dvec3(vec3(b.positions[v]));
        grow(l, p[k]);
        if (shading)
          l.normals = cone_union(
              l.normals,
              DirectionCone::around(flip * glm::normalize(glm::dvec3(vec3(b.normals[v])))));
      }
      glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
      if (!shading && glm::length(n) > 0.0)
        l.normals = cone_union(l.normals, DirectionCone::around(flip * glm::normalize(n)));
    }
    if (l.normals.empty) l.normals = DirectionCone::entire_sphere();  // degenerate triangles only
    return;
  }
  analytic_box(l, s);
  if (s.type == SHAPE_DISK) {
    glm::dvec3 n = glm::transpose(rows_to_matrix(s.to_object)) * glm::dvec3(0.0, 0.0, 1.0);
    l.normals = DirectionCone::around(flip * glm::normalize(n));
  } else {
    l.normals = DirectionCone::entire_sphere();
  }
}

// Point, spot and projector: a point with the cone of directions it emits into (the whole sphere
// where its transform does not keep angles).
void point_bounds(const SceneBuffers& b, const Emitter& e, LightBounds& l) {
  l.lo = l.hi = glm::dvec3(e.position);
  l.cos_theta_e = 0.0;
  l.normals = DirectionCone::entire_sphere();
  if (e.type == EMITTER_POINT) {
    l.phi = 4.0 * kPi * max_abs(e.radiance);
    return;
  }
  glm::dmat3 to_world = glm::inverse(rows_to_matrix(e.to_local));
  double half_angle;
  if (e.type == EMITTER_SPOT) {
    half_angle = double(e.cone.z);  // cutoff
    l.phi =
        2.0 * kPi * (1.0 - std::cos(half_angle)) * max_abs(e.radiance) * texture_mean(b, e.texture);
  } else {  // projector: the frustum |x / z| <= 1 / (2 cone.x), |y / z| <= 1 / (2 cone.y)
    double tx = 0.5 / double(e.cone.x), ty = 0.5 / double(e.cone.y);
    half_angle = std::atan(std::sqrt(tx * tx + ty * ty));
    double irradiance = e.texture != NO_INDEX ? texture_mean(b, e.texture) : max_abs(e.radiance);
    l.phi = kPi * double(e.scale) * irradiance * 4.0 * tx * ty;
  }
  if (keeps_angles(to_world))
    l.normals = {glm::normalize(to_world * glm::dvec3(0.0, 0.0, 1.0)), std::cos(half_angle), false};
}

// The bounding sphere's radius of every shape's box: infinite emitters' power goes through its
// disk (pbrt-v4 §12.5). Only a heuristic weight, so shapegroup members count in their own space.
double scene_radius(const SceneBuffers& b) {
  LightBounds all;
  all.lo = glm::dvec3(INFINITY);
  all.hi = glm::dvec3(-INFINITY);
  for (const vec4& p : b.positions) grow(all, glm::dvec3(vec3(p)));
  for (const Shape& s : b.shapes)
    if (s.type != SHAPE_MESH) analytic_box(all, s);
  return all.lo.x <= all.hi.x ? 0.5 * glm::length(all.hi - all.lo) : 1.0;
}

}  // namespace

DirectionCone cone_union(const DirectionCone& a, const DirectionCone& b) {
  if (a.empty) return b;
  if (b.empty) return a;
  const double theta_a = std::acos(std::clamp(a.cos_theta, -1.0, 1.0));
  const double theta_b = std::acos(std::clamp(b.cos_theta, -1.0, 1.0));
  const double theta_d = std::acos(std::clamp(glm::dot(a.w, b.w), -1.0, 1.0));
  if (std::min(theta_d + theta_b, kPi) <= theta_a) return a;
  if (std::min(theta_d + theta_a, kPi) <= theta_b) return b;
  const double theta_o = 0.5 * (theta_a + theta_d + theta_b);
  if (theta_o >= kPi) return DirectionCone::entire_sphere();
  const glm::dvec3 axis = glm::cross(a.w, b.w);
  if (!(glm::length(axis) > 0.0)) return DirectionCone::entire_sphere();
  // a's axis turned towards b's by theta_o - theta_a about k (Rodrigues; k is normal to a.w).
  const glm::dvec3 k = glm::normalize(axis);
  const double turn = theta_o - theta_a;
  const glm::dvec3 w = a.w * std::cos(turn) + glm::cross(k, a.w) * std::sin(turn);
  return {glm::normalize(w), std::cos(theta_o), false};
}

std::vector<LightBounds> emitter_light_bounds(const SceneBuffers& b) {
  std::vector<LightBounds> out(b.emitters.size());
  double radius = -1.0;  // computed when first needed
  for (size_t i = 0; i < b.emitters.size(); ++i) {
    const Emitter& e = b.emitters[i];
    LightBounds& l = out[i];
    switch (e.type) {
      case EMITTER_AREA:
        area_bounds(b, e, l);
        break;
      case EMITTER_POINT:
      case EMITTER_SPOT:
      case EMITTER_PROJECTOR:
        point_bounds(b, e, l);
        break;
      case EMITTER_DIRECTIONAL:
      case EMITTER_CONSTANT:
      case EMITTER_ENVMAP: {
        l.infinite = true;
        if (radius < 0.0) radius = scene_radius(b);
        const double disk = kPi * radius * radius;
        l.phi = e.type == EMITTER_DIRECTIONAL ? disk * max_abs(e.radiance)
                : e.type == EMITTER_CONSTANT  ? 4.0 * kPi * disk * max_abs(e.radiance)
                                              : 4.0 * kPi * disk * envmap_mean(b, e);
        break;
      }
      default:
        throw std::logic_error("emitter bounds: unknown emitter type");
    }
  }
  return out;
}

}  // namespace tr
