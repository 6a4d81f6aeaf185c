#include "surface_hits.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace tr {

namespace {

glm::dvec3 apply(const vec4 rows[3], const glm::dvec3& v, double w) {
  glm::dvec3 r;
  for (int i = 0; i < 3; ++i)
    r[i] = rows[i].x * v.x + rows[i].y * v.y + rows[i].z * v.z + rows[i].w * w;
  return r;
}

// n' = M^-T n with rows of M^-1 (core/transform.h).
glm::dvec3 normal_to_world(const Shape& s, const glm::dvec3& n) {
  glm::dvec3 r(0.0);
  for (int i = 0; i < 3; ++i)
    r += glm::dvec3(s.to_object[i].x, s.to_object[i].y, s.to_object[i].z) * n[i];
  return glm::normalize(r);
}

void add_triangle_hits(const SceneBuffers& b, const Shape& s, const glm::dvec3& o,
                       const glm::dvec3& d, std::vector<SurfaceHit>& hits) {
  for (uint t = 0; t < s.triangle_count; ++t) {
    glm::dvec3 p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = glm::dvec3(b.positions[s.first_vertex + b.indices[s.first_index + 3 * t + k]]);
    // Möller & Trumbore 1997.
    glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0], q = glm::cross(d, e2);
    double det = glm::dot(e1, q);
    if (det == 0.0) continue;
    glm::dvec3 r = o - p[0];
    double u = glm::dot(r, q) / det;
    glm::dvec3 rq = glm::cross(r, e1);
    double v = glm::dot(d, rq) / det, t_hit = glm::dot(e2, rq) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0 || !(t_hit > 0.0)) continue;
    // Flat meshes only (the sampler reports interpolated shading normals where a mesh has
    // them, as Mitsuba's Mesh::sample_position; the cases here have none).
    hits.push_back({o + t_hit * d, glm::normalize(glm::cross(e1, e2))});
  }
}

}  // namespace

std::vector<SurfaceHit> surface_hits(const SceneBuffers& buffers, const Shape& s,
                                     const glm::dvec3& o, const glm::dvec3& d) {
  std::vector<SurfaceHit> hits;
  if (s.type == SHAPE_MESH) {
    add_triangle_hits(buffers, s, o, d, hits);
  } else {
    // Object space: unit sphere, unit disk in z = 0, or unit cylinder x^2 + y^2 = 1, 0 <= z <= 1.
    glm::dvec3 lo = apply(s.to_object, o, 1.0), ld = apply(s.to_object, d, 0.0);
    std::vector<double> ts;
    if (s.type == SHAPE_DISK) {
      double t = -lo.z / ld.z;
      glm::dvec3 p = lo + t * ld;
      if (t > 0.0 && p.x * p.x + p.y * p.y <= 1.0) ts.push_back(t);
    } else {
      bool sphere = s.type == SHAPE_SPHERE;
      double a = ld.x * ld.x + ld.y * ld.y + (sphere ? ld.z * ld.z : 0.0);
      double bh = lo.x * ld.x + lo.y * ld.y + (sphere ? lo.z * ld.z : 0.0);
      double c = lo.x * lo.x + lo.y * lo.y + (sphere ? lo.z * lo.z : 0.0) - 1.0;
      double disc = bh * bh - a * c;
      if (disc >= 0.0 && a > 0.0) {
        for (double sign : {-1.0, 1.0}) {
          double t = (-bh + sign * std::sqrt(disc)) / a;
          double z = lo.z + t * ld.z;
          // The rims get a float-rounding margin: draws at z = 0 come back as z = -1e-8.
          if (t > 0.0 && (sphere || (z >= -1e-6 && z <= 1.0 + 1e-6))) ts.push_back(t);
        }
      }
    }
    for (double t : ts) {
      glm::dvec3 lp = lo + t * ld;
      glm::dvec3 ln = s.type == SHAPE_DISK     ? glm::dvec3(0, 0, 1)
                      : s.type == SHAPE_SPHERE ? lp
                                               : glm::dvec3(lp.x, lp.y, 0.0);
      hits.push_back({o + t * d, normal_to_world(s, ln)});
    }
  }
  if (s.flags & SHAPE_FLIP_NORMALS)
    for (SurfaceHit& h : hits) h.n = -h.n;
  return hits;
}

}  // namespace tr
