// Mitsuba `area`: radiance L leaving the front side (shading normal side) of a shape, a constant
// or a texture evaluated at the emitting point's uv (Mitsuba's m_radiance->eval(si)).
//
// Sampling picks a point on the shape and converts the area density to solid angle,
// p_w = p_A r^2 / |cos theta_l| (pbrt-v4 §4.2.3, eq. 4.9). Meshes: a triangle with
// probability proportional to its area (the emitter's alias table), then a uniform point in
// it (Heitz 2019), so p_A = 1 / total area. Spheres seen from outside: uniform cone of
// directions subtending the sphere (pbrt-v4 §6.2.4, Sphere::Sample with a reference point).
// Disks and cylinders: uniform area (their transforms must be similarities).
// A textured radiance leaves these densities as they are (twinray does not importance-sample
// the texture as Mitsuba 3 does, README.md, "Where twinray differs"): the sample's point is
// mapped to its uv as a hit there is, and the texture is read at it.
#ifndef TWINRAY_CORE_EMITTERS_AREA_H
#define TWINRAY_CORE_EMITTERS_AREA_H

#include "core/alias.h"
#include "core/emitters/emitter_sample.h"
#include "core/frame.h"
#include "core/rng.h"
#include "core/scene_access.h"
#include "core/shapes/cylinder.h"
#include "core/shapes/disk.h"
#include "core/shapes/sphere.h"
#include "core/texture.h"
#include "core/transform.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

INLINE vec3 sphere_center(IN(Shape) s) {
  return vec3(s.to_world[0].w, s.to_world[1].w, s.to_world[2].w);
}
INLINE float sphere_radius(IN(Shape) s) {
  return length(vec3(s.to_world[0].x, s.to_world[1].x, s.to_world[2].x));
}

// Whether the area emitter's radiance is a texture (Emitter.texture); only scenes with textures
// compile the lookup.
INLINE bool area_radiance_textured(IN(Emitter) e) {
  return (TR_HAS_TEXTURE(TEXTURE_BITMAP) || TR_HAS_TEXTURE(TEXTURE_CHECKERBOARD)) &&
         e.texture != NO_INDEX;
}

// The radiance the emitter leaves at a point of its surface with this uv.
INLINE vec3 area_radiance(IN(Emitter) e, vec2 uv) {
  return area_radiance_textured(e) ? eval_texture(e.texture, uv) : e.radiance;
}

// sin^2(1.5 degrees): below it, cone quantities use Taylor expansions (pbrt-v4 §6.2.4).
const float SMALL_CONE_SIN2 = 0.00068523f;

// 1 - cos(theta_max) of the cone of directions from p that hits the sphere, accurate for
// small cones; returns false when p is inside (or on) the sphere, where no cone exists.
INLINE bool sphere_cone(IN(Shape) s, vec3 p, OUT(float) one_minus_cos_max) {
  vec3 c = sphere_center(s);
  float r = sphere_radius(s);
  float dist2 = dot(c - p, c - p);
  if (dist2 <= r * r * 1.0001f) return false;
  float sin2_max = r * r / dist2;
  one_minus_cos_max =
      sin2_max < SMALL_CONE_SIN2 ? 0.5f * sin2_max : 1.0f - safe_sqrt(1.0f - sin2_max);
  return true;
}

// A point on the emitter's mesh, uniform in area, with its normal (shading normals interpolated
// where present, as Mitsuba's Mesh::sample_position) and, for a textured radiance, its uv (the
// vertex uvs interpolated, as at a hit; the loader refuses such a mesh without uvs). Reads the
// emitter's copies of its shape's fields only.
INLINE void sample_mesh_area(IN(Emitter) e, INOUT(Rng) rng, OUT(vec3) p, OUT(vec3) n,
                             OUT(vec2) uv) {
  // As Mitsuba 3's Mesh::sample_position, one 2D number picks the triangle (its x) and,
  // rescaled, places the point in it: the point set a correlated sampler stratifies in 2D
  // stays stratified over the whole shape, not over each triangle apart. Meshes of more
  // triangles than ALIAS_REUSE_MAX_COUNT take a second number for the point.
  vec2 u = rng_next_2d(rng);
  bool has_normals = (e.shape_flags & SHAPE_HAS_NORMALS) != 0u;
  vec3 p0, p1, p2;
  vec3 n0 = vec3(0.0f), n1 = vec3(0.0f), n2 = vec3(0.0f);
  uint base = e.first_index;  // the triangle's first entry in the index buffer
  if (e.alias_count == 1u) {
    // A mesh of one triangle carries it in its record (Emitter.to_world, to_local): with many
    // such emitters, the table entry, indices, vertices and normals would each be a dependent
    // cache miss. Its one-entry table (q = 1) would return u as it is.
    p0 = vec3(e.to_world[0]);
    p1 = vec3(e.to_world[1]);
    p2 = vec3(e.to_world[2]);
    if (has_normals) {
      n0 = vec3(e.to_local[0]);
      n1 = vec3(e.to_local[1]);
      n2 = vec3(e.to_local[2]);
    }
  } else {
    float pmf;
    uint tri;
    if (e.alias_count <= ALIAS_REUSE_MAX_COUNT) {
      tri = alias_sample_reuse(e.alias_offset, e.alias_count, u.x, pmf, u.x);
    } else {
      tri = alias_sample(e.alias_offset, e.alias_count, u, pmf);
      u = rng_next_2d(rng);
    }
    base += 3u * tri;
    uint i0 = e.first_vertex + scene_index(base);
    uint i1 = e.first_vertex + scene_index(base + 1u);
    uint i2 = e.first_vertex + scene_index(base + 2u);
    p0 = scene_position(i0);
    p1 = scene_position(i1);
    p2 = scene_position(i2);
    if (has_normals) {
      n0 = scene_normal(i0);
      n1 = scene_normal(i1);
      n2 = scene_normal(i2);
    }
  }
  vec2 b = square_to_uniform_triangle(u);
  float b0 = 1.0f - b.x - b.y;
  p = b0 * p0 + b.x * p1 + b.y * p2;
  if (has_normals)
    n = normalize(b0 * n0 + b.x * n1 + b.y * n2);
  else
    n = normalize(cross(p1 - p0, p2 - p0));
  uv = vec2(0.0f);
  if (area_radiance_textured(e)) {
    vec2 uv0 = scene_uv(e.first_vertex + scene_index(base));
    vec2 uv1 = scene_uv(e.first_vertex + scene_index(base + 1u));
    vec2 uv2 = scene_uv(e.first_vertex + scene_index(base + 2u));
    uv = b0 * uv0 + b.x * uv1 + b.y * uv2;
  }
}

// A point on an analytic shape (sphere, disk, cylinder), uniform in area, with its normal and,
// when `textured`, its uv (Mitsuba's parameterization of the shape, as at a hit).
INLINE void sample_analytic_area(IN(Shape) s, bool textured, INOUT(Rng) rng, OUT(vec3) p,
                                 OUT(vec3) n, OUT(vec2) uv) {
  vec2 u = rng_next_2d(rng);
  vec3 local;
  vec3 n_local;
  if (s.type == SHAPE_SPHERE) {
    local = square_to_uniform_sphere(u);
    n_local = local;
  } else if (s.type == SHAPE_DISK) {
    vec2 d = square_to_uniform_disk_concentric(u);
    local = vec3(d.x, d.y, 0.0f);
    n_local = vec3(0.0f, 0.0f, 1.0f);
  } else {
    float phi = 2.0f * PI * u.y;
    local = vec3(cos(phi), sin(phi), u.x);
    n_local = vec3(local.x, local.y, 0.0f);
  }
  p = transform_point(s.to_world[0], s.to_world[1], s.to_world[2], local);
  n = normalize(transform_normal(s.to_object[0], s.to_object[1], s.to_object[2], n_local));
  uv = vec2(0.0f);
  if (textured) {
    if (s.type == SHAPE_SPHERE)
      uv = unit_sphere_uv(local);
    else if (s.type == SHAPE_DISK)
      uv = unit_disk_uv(local);
    else
      uv = unit_cylinder_uv(local);
  }
}

INLINE EmitterSample sample_area_emitter(IN(Emitter) e, vec3 ref_p, INOUT(Rng) rng) {
  EmitterSample s = emitter_sample_failed();
  bool textured = area_radiance_textured(e);
  vec2 uv = vec2(0.0f);
  float one_minus_cos_max;
  if (TR_HAS_SHAPE(SHAPE_SPHERE) && e.shape_type == SHAPE_SPHERE &&
      sphere_cone(scene_shape(e.shape), ref_p, one_minus_cos_max)) {
    REF(Shape) shape = scene_shape(e.shape);
    // pbrt-v4 §6.2.4: sample cos(theta) in the cone, then the sphere point whose direction
    // from the centre makes angle alpha with the axis (law of cosines).
    vec2 u = rng_next_2d(rng);
    vec3 c = sphere_center(shape);
    float r = sphere_radius(shape);
    float dc = length(c - ref_p);
    float sin_max = r / dc;
    float sin2_max = sin_max * sin_max;
    float cos_theta = 1.0f - u.x * one_minus_cos_max;
    float sin2_theta = 1.0f - cos_theta * cos_theta;
    if (sin2_max < SMALL_CONE_SIN2) {
      sin2_theta = sin2_max * u.x;
      cos_theta = sqrt(1.0f - sin2_theta);
    }
    float cos_alpha = sin2_theta / sin_max + cos_theta * safe_sqrt(1.0f - sin2_theta / sin2_max);
    float sin_alpha = safe_sqrt(1.0f - cos_alpha * cos_alpha);
    float phi = 2.0f * PI * u.y;
    Frame f = frame_from_normal((ref_p - c) / dc);
    vec3 w = frame_to_world(f, vec3(sin_alpha * cos(phi), sin_alpha * sin(phi), cos_alpha));
    s.p = c + r * w;
    s.n = w;
    vec3 v = s.p - ref_p;
    s.dist = length(v);
    s.d = v / s.dist;
    s.pdf = 1.0f / (2.0f * PI * one_minus_cos_max);
    if (textured)  // the point in the unit sphere's space, as a hit reprojects it
      uv = unit_sphere_uv(normalize(
          transform_point(shape.to_object[0], shape.to_object[1], shape.to_object[2], s.p)));
  } else {
    vec3 p;
    vec3 n;
    if (TR_HAS_SHAPE(SHAPE_MESH) && e.shape_type == SHAPE_MESH)
      sample_mesh_area(e, rng, p, n, uv);
    else
      sample_analytic_area(scene_shape(e.shape), textured, rng, p, n, uv);
    vec3 v = p - ref_p;
    float dist2 = dot(v, v);
    if (!(dist2 > 0.0f)) return s;
    s.p = p;
    s.n = n;
    s.dist = sqrt(dist2);
    s.d = v / s.dist;
    float cos_l = abs(dot(n, s.d));
    if (!(cos_l > 0.0f)) return s;
    s.pdf = dist2 / (cos_l * e.area);
  }
  if ((e.shape_flags & SHAPE_FLIP_NORMALS) != 0u) s.n = -s.n;
  // One-sided emission: only the side the normal faces emits (Mitsuba's area emitter).
  // Points seen exactly edge-on (the reference point in the emitter's own plane) have an
  // unbounded density and carry no energy: the sample fails.
  if (!(dot(s.n, s.d) < 0.0f) || !(s.pdf < FLOAT_MAX)) {
    s.pdf = 0.0f;
    return s;
  }
  s.weight = area_radiance(e, uv) / s.pdf;
  return s;
}

// Solid-angle density with which sample_area_emitter produces the point p (normal n)
// from ref_p.
INLINE float pdf_area_emitter(IN(Emitter) e, vec3 ref_p, vec3 p, vec3 n) {
  float one_minus_cos_max;
  if (TR_HAS_SHAPE(SHAPE_SPHERE) && e.shape_type == SHAPE_SPHERE &&
      sphere_cone(scene_shape(e.shape), ref_p, one_minus_cos_max))
    return 1.0f / (2.0f * PI * one_minus_cos_max);
  vec3 v = p - ref_p;
  float dist2 = dot(v, v);
  float cos_l = abs(dot(n, v)) * inversesqrt(dist2);
  if (!(cos_l > 0.0f)) return 0.0f;
  return dist2 / (cos_l * e.area);
}

// Radiance leaving the emitter's point of this uv towards wi (local shading frame of the
// emitter's surface).
INLINE vec3 eval_area_emitter(IN(Emitter) e, vec3 wi_local, vec2 uv) {
  return wi_local.z > 0.0f ? area_radiance(e, uv) : vec3(0.0f);
}

TR_NAMESPACE_END

#endif
