// Mitsuba's `perspective`, `thinlens` and `orthographic` sensors (src/sensors/*.cpp).
//
// Camera space looks along +z with +x to the left and +y up (Mitsuba). A film position s in
// [0,1]^2 of the full film (origin at the top-left corner) maps to the camera-space point
// ((1 - 2 s_x) e_x, (1 - 2 s_y) e_y), e = Camera.half_extent, the inverse of Mitsuba's
// perspective_projection / orthographic_projection (include/mitsuba/render/sensor.h; a crop
// window only selects which film positions are sampled). Perspective and thin lens read it
// at z = 1, as a direction; orthographic on the near plane, as the ray's origin. Rays span the
// near to the far clip plane.
#ifndef TWINRAY_CORE_CAMERA_H
#define TWINRAY_CORE_CAMERA_H

#include "core/ray.h"
#include "core/scene_types.h"
#include "core/transform.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

// Primary ray through film position `film` (pixels of the full film); u_lens feeds the
// thin lens's aperture sample.
INLINE Ray camera_ray(IN(Camera) c, vec2 film, vec2 u_lens) {
  vec2 s = film / c.film_size;
  if (c.type == SENSOR_ORTHOGRAPHIC) {
    // orthographic.cpp: origin on the near plane through to_world (scale included), direction
    // to_world's +z, tmax = far - near.
    vec3 p = vec3((1.0f - 2.0f * s.x) * c.half_extent.x, (1.0f - 2.0f * s.y) * c.half_extent.y,
                  c.near_clip);
    Ray ray;
    ray.o = transform_point(c.to_world[0], c.to_world[1], c.to_world[2], p);
    ray.tmin = 0.0f;
    ray.d = normalize(
        transform_vector(c.to_world[0], c.to_world[1], c.to_world[2], vec3(0.0f, 0.0f, 1.0f)));
    ray.tmax = c.far_clip - c.near_clip;
    return ray;
  }
  // perspective.cpp adds principal_point_offset to the film sample before unprojecting
  // (thinlens reads no offset; the loader leaves it 0).
  s += c.principal_point;
  vec3 d = normalize(
      vec3((1.0f - 2.0f * s.x) * c.half_extent.x, (1.0f - 2.0f * s.y) * c.half_extent.y, 1.0f));
  vec3 o = vec3(0.0f);
  if (c.type == SENSOR_THINLENS) {
    // thinlens.cpp: a point on the aperture disk, aimed at the point of the plane of focus
    // that the pinhole ray reaches (pbrt-v4 §5.2.3).
    vec2 lens = c.aperture_radius * square_to_uniform_disk_concentric(u_lens);
    vec3 focus = d * (c.focus_distance / d.z);
    o = vec3(lens, 0.0f);
    d = normalize(focus - o);
  }
  float inv_z = 1.0f / d.z;
  float near_t = c.near_clip * inv_z;
  float far_t = c.far_clip * inv_z;
  vec3 o_world = transform_point(c.to_world[0], c.to_world[1], c.to_world[2], o);
  vec3 d_world = normalize(transform_vector(c.to_world[0], c.to_world[1], c.to_world[2], d));
  Ray ray;
  ray.o = o_world + d_world * near_t;
  ray.tmin = 0.0f;
  ray.d = d_world;
  ray.tmax = far_t - near_t;
  return ray;
}

TR_NAMESPACE_END

#endif
