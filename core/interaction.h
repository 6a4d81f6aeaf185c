// Surface interactions: everything the light-transport code needs at a ray hit, rebuilt from
// a backend's Hit record and the scene buffers (identical on every backend).
#ifndef TWINRAY_CORE_INTERACTION_H
#define TWINRAY_CORE_INTERACTION_H

#include "core/frame.h"
#include "core/hit.h"
#include "core/ray.h"
#include "core/scene_access.h"
#include "core/shapes/cylinder.h"
#include "core/shapes/disk.h"
#include "core/shapes/sphere.h"
#include "core/texture.h"
#include "core/transform.h"

TR_NAMESPACE_BEGIN

struct SurfaceInteraction {
  vec3 p;   // world-space position
  float t;  // ray parameter
  vec3 ng;  // geometric normal (unit; winding / flip_normals orientation, as Mitsuba)
  uint shape;
  Frame frame;  // shading frame, frame.n = shading normal
  vec3 wi;      // direction towards the ray origin, in the shading frame
  uint material;
  vec2 uv;
  uint emitter;  // NO_INDEX unless the shape is an area emitter
  uint instance;
  vec3 dp_du;  // Mitsuba's partial derivatives of the position in uv (world space)
  vec3 dp_dv;
  vec2 barycentrics;  // meshes: (b1, b2) in the triangle hit
  uint primitive;     // meshes: the triangle hit
};

// Where the textures of the hit surface are evaluated (mesh attributes need the triangle).
INLINE TexCoord surface_tex_coord(IN(SurfaceInteraction) si) {
  return tex_coord_mesh(si.uv, si.shape, si.primitive, si.barycentrics);
}

// Mitsuba's shading frame: s follows dp/du projected onto the tangent plane when the
// parameterization provides it, otherwise Duff et al.'s basis (Mitsuba coordinate_system).
INLINE Frame shading_frame(vec3 n, vec3 dp_du) {
  vec3 s = dp_du - n * dot(n, dp_du);
  float len2 = dot(s, s);
  if (!(len2 > 1e-20f)) return frame_from_normal(n);
  Frame f;
  f.n = n;
  f.s = s * inversesqrt(len2);
  f.t = cross(n, f.s);
  return f;
}

// The frame of a mesh with vertex tangents (twinray's `vertex_tangents`; glTF 2.0 "Meshes":
// bitangent = w (normal x tangent)): s is the interpolated tangent made orthogonal to n (Gram-
// Schmidt), t = +-(n x s) on the side of the interpolated bitangent, so a normal map's green
// channel follows the bitangent on mirrored uvs too. Where no tangent is left, Mitsuba's frame.
INLINE Frame tangent_frame(vec3 n, vec3 tangent, vec3 bitangent, vec3 dp_du) {
  vec3 s = tangent - n * dot(n, tangent);
  float len2 = dot(s, s);
  if (!(len2 > 1e-20f)) return shading_frame(n, dp_du);
  Frame f;
  f.n = n;
  f.s = s * inversesqrt(len2);
  f.t = cross(n, f.s);
  if (dot(f.t, bitangent) < 0.0f) f.t = -f.t;
  return f;
}

// A point, vector or normal of an instance's space in world space; instance 0, the scene's
// own shapes, is the identity and skips the arithmetic (which could only flip signs of zero).
INLINE vec3 instance_point(uint index, IN(Instance) inst, vec3 p) {
  return index == 0u ? p : transform_point(inst.to_world[0], inst.to_world[1], inst.to_world[2], p);
}
INLINE vec3 instance_vector(uint index, IN(Instance) inst, vec3 v) {
  return index == 0u ? v
                     : transform_vector(inst.to_world[0], inst.to_world[1], inst.to_world[2], v);
}
INLINE vec3 instance_normal(uint index, IN(Instance) inst, vec3 n) {
  return index == 0u ? n
                     : transform_normal(inst.to_object[0], inst.to_object[1], inst.to_object[2], n);
}

INLINE SurfaceInteraction surface_interaction(IN(Ray) ray, IN(Hit) hit) {
  REF(Shape) shape = scene_shape(hit.shape);
  REF(Instance) inst = scene_instance(hit.instance);
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = hit.shape;
  si.instance = hit.instance;
  si.material = shape.material;
  si.emitter = shape.emitter;
  si.barycentrics = hit.barycentrics;
  si.primitive = hit.primitive;
  // Mitsuba's partials dp/du, dp/dv: only `bumpmap` reads them (zero where it cannot).
  bool partials = TR_HAS_BSDF(BSDF_BUMPMAP);
  si.dp_du = vec3(0.0f);
  si.dp_dv = vec3(0.0f);
  vec3 n_shading;
  vec3 dp_du = vec3(0.0f);
  bool tangents = false;
  vec3 tangent = vec3(0.0f);
  vec3 bitangent = vec3(0.0f);
  if (TR_HAS_SHAPE(SHAPE_MESH) && shape.type == SHAPE_MESH) {
    uint base = shape.first_index + 3u * hit.primitive;
    uint v0 = scene_index(base);
    uint v1 = scene_index(base + 1u);
    uint v2 = scene_index(base + 2u);
    uint i0 = shape.first_vertex + v0;
    uint i1 = shape.first_vertex + v1;
    uint i2 = shape.first_vertex + v2;
    vec3 p0 = instance_point(hit.instance, inst, scene_position(i0));
    vec3 p1 = instance_point(hit.instance, inst, scene_position(i1));
    vec3 p2 = instance_point(hit.instance, inst, scene_position(i2));
    float b1 = hit.barycentrics.x;
    float b2 = hit.barycentrics.y;
    float b0 = 1.0f - b1 - b2;
    si.p = b0 * p0 + b1 * p1 + b2 * p2;
    vec3 face_n = normalize(cross(p1 - p0, p2 - p0));
    si.ng = (shape.flags & SHAPE_FLIP_NORMALS) != 0u ? -face_n : face_n;
    n_shading = si.ng;
    if ((shape.flags & SHAPE_HAS_NORMALS) != 0u) {
      vec3 n = b0 * scene_normal(i0) + b1 * scene_normal(i1) + b2 * scene_normal(i2);
      n_shading = normalize(instance_normal(hit.instance, inst, n));
      if ((shape.flags & SHAPE_FLIP_NORMALS) != 0u) n_shading = -n_shading;
    }
    tangents = (shape.flags & SHAPE_HAS_TANGENTS) != 0u;
    if (tangents) {
      uint t_words = shape.tangent_frames;
      uint b_words = t_words + 3u * shape.vertex_count;
      tangent = b0 * mesh_attribute_value(t_words, 3u, v0) +
                b1 * mesh_attribute_value(t_words, 3u, v1) +
                b2 * mesh_attribute_value(t_words, 3u, v2);
      bitangent = b0 * mesh_attribute_value(b_words, 3u, v0) +
                  b1 * mesh_attribute_value(b_words, 3u, v1) +
                  b2 * mesh_attribute_value(b_words, 3u, v2);
      tangent = instance_vector(hit.instance, inst, tangent);
      bitangent = instance_vector(hit.instance, inst, bitangent);
    }
    si.uv = vec2(b1, b2);
    if (partials) {
      // Without uvs Mitsuba (src/render/mesh.cpp) takes dp/du, dp/dv from coordinate_system of
      // the face normal before flip_normals.
      Frame face = frame_from_normal(face_n);
      si.dp_du = face.s;
      si.dp_dv = face.t;
    }
    if ((shape.flags & SHAPE_HAS_UVS) != 0u) {
      vec2 uv0 = scene_uv(i0);
      vec2 uv1 = scene_uv(i1);
      vec2 uv2 = scene_uv(i2);
      si.uv = b0 * uv0 + b1 * uv1 + b2 * uv2;
      // dp/du from the triangle's uv parameterization (pbrt-v4 §6.5.3, eq. 6.7).
      vec2 duv02 = uv0 - uv2;
      vec2 duv12 = uv1 - uv2;
      float det = duv02.x * duv12.y - duv02.y * duv12.x;
      if (abs(det) > 1e-20f) dp_du = (duv12.y * (p0 - p2) - duv02.y * (p1 - p2)) / det;
      // Mitsuba's dp/du, dp/dv (pbrt-v4 eq. 6.7, edges from vertex 0), when det != 0.
      vec2 duv0 = uv1 - uv0;
      vec2 duv1 = uv2 - uv0;
      float det0 = duv0.x * duv1.y - duv0.y * duv1.x;
      if (partials && det0 != 0.0f) {
        si.dp_du = (duv1.y * (p1 - p0) - duv0.y * (p2 - p0)) / det0;
        si.dp_dv = (duv0.x * (p2 - p0) - duv1.x * (p1 - p0)) / det0;
      }
    }
  } else {
    vec3 p_inst = ray.o + hit.t * ray.d;
    if (hit.instance != 0u)
      p_inst = transform_point(inst.to_object[0], inst.to_object[1], inst.to_object[2], p_inst);
    vec3 local =
        transform_point(shape.to_object[0], shape.to_object[1], shape.to_object[2], p_inst);
    vec3 n_local;
    vec3 dp_du_local;
    vec3 dpdu_local;  // Mitsuba's dp/du, dp/dv in the shape's local space
    vec3 dpdv_local;
    if (TR_HAS_SHAPE(SHAPE_SPHERE) && shape.type == SHAPE_SPHERE) {
      local = normalize(local);  // reproject onto the surface, as Mitsuba
      n_local = local;
      si.uv = unit_sphere_uv(local);
      dp_du_local = vec3(-local.y, local.x, 0.0f);
      // src/shapes/sphere.cpp: 2 pi (-y, x, 0) and pi (z cos phi, z sin phi, -r_xy), with
      // dp/dv = (1, 0, 0) at the poles.
      dpdu_local = 2.0f * PI * dp_du_local;
      float rd = sqrt(local.x * local.x + local.y * local.y);
      dpdv_local = rd == 0.0f ? vec3(PI, 0.0f, 0.0f)
                              : PI * vec3(local.z * local.x / rd, local.z * local.y / rd, -rd);
    } else if (TR_HAS_SHAPE(SHAPE_DISK) && shape.type == SHAPE_DISK) {
      local.z = 0.0f;
      n_local = vec3(0.0f, 0.0f, 1.0f);
      si.uv = unit_disk_uv(local);
      dp_du_local = vec3(local.x, local.y, 0.0f);
      // src/shapes/disk.cpp: (cos phi, sin phi, 0) and (-sin phi, cos phi, 0), phi = 0 at r = 0.
      float r = sqrt(local.x * local.x + local.y * local.y);
      vec2 cs = r == 0.0f ? vec2(1.0f, 0.0f) : vec2(local.x, local.y) / r;
      dpdu_local = vec3(cs.x, cs.y, 0.0f);
      dpdv_local = vec3(-cs.y, cs.x, 0.0f);
    } else {
      n_local = vec3(local.x, local.y, 0.0f);
      si.uv = unit_cylinder_uv(local);
      dp_du_local = vec3(-local.y, local.x, 0.0f);
      // src/shapes/cylinder.cpp: 2 pi (-y, x, 0) and (0, 0, 1).
      dpdu_local = 2.0f * PI * dp_du_local;
      dpdv_local = vec3(0.0f, 0.0f, 1.0f);
    }
    if (partials) {
      si.dp_du =
          transform_vector(shape.to_world[0], shape.to_world[1], shape.to_world[2], dpdu_local);
      si.dp_du = instance_vector(hit.instance, inst, si.dp_du);
      si.dp_dv =
          transform_vector(shape.to_world[0], shape.to_world[1], shape.to_world[2], dpdv_local);
      si.dp_dv = instance_vector(hit.instance, inst, si.dp_dv);
    }
    vec3 p_world = transform_point(shape.to_world[0], shape.to_world[1], shape.to_world[2], local);
    si.p = instance_point(hit.instance, inst, p_world);
    vec3 n = transform_normal(shape.to_object[0], shape.to_object[1], shape.to_object[2], n_local);
    si.ng = normalize(instance_normal(hit.instance, inst, n));
    if ((shape.flags & SHAPE_FLIP_NORMALS) != 0u) si.ng = -si.ng;
    n_shading = si.ng;
    dp_du = transform_vector(shape.to_world[0], shape.to_world[1], shape.to_world[2], dp_du_local);
    dp_du = instance_vector(hit.instance, inst, dp_du);
  }
  si.frame = tangents ? tangent_frame(n_shading, tangent, bitangent, dp_du)
                      : shading_frame(n_shading, dp_du);
  si.wi = frame_to_local(si.frame, -ray.d);
  return si;
}

TR_NAMESPACE_END

#endif
