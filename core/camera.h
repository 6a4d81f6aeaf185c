// Mitsuba's `perspective` and `thinlens` sensors and the film's reconstruction filter.
//
// Camera space looks along +z with +x to the left and +y up (Mitsuba). A film position
// s in [0,1]^2 (origin at the top-left corner) maps to the near-plane direction
// ((1 - 2 s_x) tan(fov_x / 2), (1 - 2 s_y) tan(fov_y / 2), 1), the inverse of Mitsuba's
// camera_to_sample projection. Rays start at the near clip plane and end at the far one.
#ifndef TWINRAY_CORE_CAMERA_H
#define TWINRAY_CORE_CAMERA_H

#include "core/ray.h"
#include "core/scene_types.h"
#include "core/special_functions.h"
#include "core/transform.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

// One axis of the gaussian filter, importance sampled: x follows the normal density of
// standard deviation sigma truncated to [-r, r], by inversion of its CDF (pbrt-v4 §A.4.2
// for the truncated-normal inversion); the returned weight f(x) / (pdf(x) integral(f)) makes
// the estimate that of the normalized filter. It is 1 - exp(-(r^2 - x^2) / 2 sigma^2) up to a
// constant, so nearly uniform (pbrt-v4 §8.8.2, filter importance sampling).
INLINE float sample_gaussian_filter_1d(float u, float sigma, float r, OUT(float) weight) {
  float e = erf_approx(r / (sigma * sqrt(2.0f)));
  float x = clamp(sigma * sqrt(2.0f) * erfinv_approx(e * (2.0f * u - 1.0f)), -r, r);
  float gauss_integral = sigma * sqrt(2.0f * PI) * e;  // of exp(-x^2 / 2 sigma^2) over [-r, r]
  float filter_integral = gauss_integral - 2.0f * r * exp(-0.5f * r * r / (sigma * sigma));
  weight =
      (1.0f - exp(-0.5f * (r * r - x * x) / (sigma * sigma))) * gauss_integral / filter_integral;
  return x;
}

// Position of a sample on the film (pixels, relative to the full film's top-left) around
// the centre of `pixel`, and its filter weight. Box: uniform over the pixel, weight 1.
// Gaussian: each axis importance sampled (sample_gaussian_filter_1d); every sample stays in
// its own pixel's estimate (Mitsuba splats samples over neighbouring pixels instead; both
// estimate the same filtered image).
INLINE vec2 sample_film_position(Camera c, uvec2 pixel, vec2 u, OUT(float) weight) {
  vec2 center = vec2(pixel) + vec2(0.5f) + vec2(float(c.crop_offset_x), float(c.crop_offset_y));
  if (c.rfilter == RFILTER_BOX) {
    weight = 1.0f;
    return center + (u - vec2(0.5f));
  }
  float wx;
  float wy;
  float x = sample_gaussian_filter_1d(u.x, c.filter_stddev, c.filter_radius, wx);
  float y = sample_gaussian_filter_1d(u.y, c.filter_stddev, c.filter_radius, wy);
  weight = wx * wy;
  return center + vec2(x, y);
}

// Primary ray through film position `film` (pixels of the full film); u_lens feeds the
// thin lens's aperture sample.
INLINE Ray camera_ray(Camera c, vec2 film, vec2 u_lens) {
  // Mitsuba adds principal_point_offset to the film sample before unprojecting.
  vec2 s = film / vec2(float(c.width), float(c.height)) + c.principal_point;
  vec3 d = normalize(
      vec3((1.0f - 2.0f * s.x) * c.tan_half_fov.x, (1.0f - 2.0f * s.y) * c.tan_half_fov.y, 1.0f));
  vec3 o = vec3(0.0f);
  if (c.type == SENSOR_THINLENS) {
    // Mitsuba thinlens: a point on the aperture disk, aimed at the point of the plane of focus
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
