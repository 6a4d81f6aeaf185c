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
#include "core/transform.h"
#include "core/warp.h"

TR_NAMESPACE_BEGIN

// Error function, Abramowitz & Stegun 7.1.26 (|error| <= 1.5e-7).
INLINE float erf_approx(float x) {
  float s = x < 0.0f ? -1.0f : 1.0f;
  float a = abs(x);
  float t = 1.0f / (1.0f + 0.3275911f * a);
  float y = 1.0f - (((((1.061405429f * t - 1.453152027f) * t) + 1.421413741f) * t - 0.284496736f) * t +
                    0.254829592f) * t * exp(-a * a);
  return s * y;
}

// Mitsuba's gaussian filter, shifted to reach zero at the radius r:
// f(x) = max(0, exp(-x^2 / 2 sigma^2) - exp(-r^2 / 2 sigma^2)).
INLINE float gaussian_filter_1d(float x, float sigma, float r) {
  float k = -0.5f / (sigma * sigma);
  return max(0.0f, exp(k * x * x) - exp(k * r * r));
}

// Integral of gaussian_filter_1d over [-r, r].
INLINE float gaussian_filter_1d_integral(float sigma, float r) {
  return sigma * sqrt(2.0f * PI) * erf_approx(r / (sigma * sqrt(2.0f))) -
         2.0f * r * exp(-0.5f * r * r / (sigma * sigma));
}

// Position of a sample on the film (pixels, relative to the full film's top-left) around
// the centre of `pixel`, and its filter weight. Box: uniform over the pixel, weight 1.
// Gaussian: uniform over the filter's square support with weight f(x) f(y) |support| /
// (integral of f)^2, an unbiased estimate of the normalized filter convolution that keeps
// every sample inside its own pixel's estimate (Mitsuba splats instead; same expectation).
INLINE vec2 sample_film_position(Camera c, uvec2 pixel, vec2 u, OUT(float) weight) {
  vec2 center = vec2(pixel) + vec2(0.5f) + vec2(float(c.crop_offset_x), float(c.crop_offset_y));
  if (c.rfilter == RFILTER_BOX) {
    weight = 1.0f;
    return center + (u - vec2(0.5f));
  }
  float r = c.filter_radius;
  vec2 offset = (2.0f * u - vec2(1.0f)) * r;
  float norm = gaussian_filter_1d_integral(c.filter_stddev, r);
  weight = gaussian_filter_1d(offset.x, c.filter_stddev, r) * gaussian_filter_1d(offset.y, c.filter_stddev, r) *
           (4.0f * r * r) / (norm * norm);
  return center + offset;
}

// Primary ray through film position `film` (pixels of the full film); u_lens feeds the
// thin lens's aperture sample.
INLINE Ray camera_ray(Camera c, vec2 film, vec2 u_lens) {
  vec2 s = film / vec2(float(c.width), float(c.height)) - c.principal_point;
  vec3 d = normalize(vec3((1.0f - 2.0f * s.x) * c.tan_half_fov.x, (1.0f - 2.0f * s.y) * c.tan_half_fov.y, 1.0f));
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
