// Warps from the unit square to common sampling domains, with their densities.
// Formulas: pbrt-v4 (Pharr, Jakob, Humphreys), §A.5 "Sampling Multidimensional Functions";
// triangle: Heitz, "A Low-Distortion Map Between Triangle and Square", 2019.
#ifndef TWINRAY_CORE_WARP_H
#define TWINRAY_CORE_WARP_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// Shirley-Chiu concentric map, pbrt-v4 §A.5.1 (SampleUniformDiskConcentric).
INLINE vec2 square_to_uniform_disk_concentric(vec2 u) {
  vec2 o = 2.0f * u - vec2(1.0f);
  if (o.x == 0.0f && o.y == 0.0f) return vec2(0.0f);
  float r;
  float theta;
  if (abs(o.x) > abs(o.y)) {
    r = o.x;
    theta = (PI / 4.0f) * (o.y / o.x);
  } else {
    r = o.y;
    theta = (PI / 2.0f) - (PI / 4.0f) * (o.x / o.y);
  }
  return r * vec2(cos(theta), sin(theta));
}
INLINE float square_to_uniform_disk_concentric_pdf(vec2 p) {
  return dot(p, p) <= 1.0f ? INV_PI : 0.0f;
}

// Malley's method, pbrt-v4 §A.5.3: pdf = cos(theta) / pi.
INLINE vec3 square_to_cosine_hemisphere(vec2 u) {
  vec2 d = square_to_uniform_disk_concentric(u);
  float z = safe_sqrt(1.0f - dot(d, d));
  return vec3(d.x, d.y, z);
}
INLINE float square_to_cosine_hemisphere_pdf(vec3 w) { return w.z > 0.0f ? w.z * INV_PI : 0.0f; }

// pbrt-v4 §A.5.2 (SampleUniformSphere): pdf = 1 / (4 pi).
INLINE vec3 square_to_uniform_sphere(vec2 u) {
  float z = 1.0f - 2.0f * u.x;
  float r = safe_sqrt(1.0f - z * z);
  float phi = 2.0f * PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}
INLINE float square_to_uniform_sphere_pdf(vec3 w) { return INV_FOUR_PI; }

// pbrt-v4 §A.5.2 (SampleUniformHemisphere): pdf = 1 / (2 pi).
INLINE vec3 square_to_uniform_hemisphere(vec2 u) {
  float z = u.x;
  float r = safe_sqrt(1.0f - z * z);
  float phi = 2.0f * PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}
INLINE float square_to_uniform_hemisphere_pdf(vec3 w) { return w.z >= 0.0f ? INV_TWO_PI : 0.0f; }

// Uniform cone around +z with cos(theta_max) = cos_max, pbrt-v4 §A.5.4 (SampleUniformCone).
INLINE vec3 square_to_uniform_cone(vec2 u, float cos_max) {
  float cos_theta = (1.0f - u.x) + u.x * cos_max;
  float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
  float phi = 2.0f * PI * u.y;
  return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}
INLINE float square_to_uniform_cone_pdf(vec3 w, float cos_max) {
  return w.z >= cos_max ? 1.0f / (2.0f * PI * (1.0f - cos_max)) : 0.0f;
}

// Barycentrics (b1, b2) of a uniform point on a triangle, Heitz 2019, Listing 1;
// the point is (1 - b1 - b2) p0 + b1 p1 + b2 p2, pdf = 1 / area.
INLINE vec2 square_to_uniform_triangle(vec2 u) {
  float b0;
  float b1;
  if (u.y > u.x) {
    b0 = u.x * 0.5f;
    b1 = u.y - b0;
  } else {
    b1 = u.y * 0.5f;
    b0 = u.x - b1;
  }
  return vec2(b0, b1);
}

TR_NAMESPACE_END

#endif
