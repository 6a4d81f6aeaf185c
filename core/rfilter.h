// Mitsuba 3's reconstruction filters (src/rfilters/*.cpp) and the table through which its
// scalar variants evaluate them (include/mitsuba/core/rfilter.h, eval_discretized, filled by
// src/core/rfilter.cpp init_discretization). The scene builder fills Camera.filter_table from
// these; core/film.h samples the film from the table.
//
// Each filter is a function of one coordinate x (pixels); the 2D filter is f(x) f(y).
#ifndef TWINRAY_CORE_RFILTER_H
#define TWINRAY_CORE_RFILTER_H

#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

// MI_FILTER_RESOLUTION: the table holds f(r i / 31) for i < 31 and 0 at i = 31.
const uint FILTER_RESOLUTION = 31u;

// tent.cpp: max(0, 1 - |x| / radius).
INLINE float rfilter_tent(float x, float radius) {
  return max(0.0f, 1.0f - abs(x * (1.0f / radius)));
}

// gaussian.cpp: the gaussian of standard deviation `stddev` minus its value at the radius
// 4 stddev, through Mitsuba's Remez fit to exp(-x / 2) on [0, 16] (a degree-9 polynomial in
// x^2 / stddev^2, constant term shifted so that it vanishes at the radius), clamped at 0.
INLINE float gaussian_remez(float x2, float inv_var) {
  // Coefficients of the fit in t = x^2 / stddev^2 (gaussian.cpp, `coeff`), by Horner's rule.
  float c[10];
  c[0] = 9.992604880e-1f;
  c[1] = -4.977025247e-1f;
  c[2] = 1.222248550e-1f;
  c[3] = -1.932406282e-2f;
  c[4] = 2.136713061e-3f;
  c[5] = -1.679873860e-4f;
  c[6] = 9.202145248e-6f;
  c[7] = -3.329417433e-7f;
  c[8] = 7.128382794e-9f;
  c[9] = -6.821193280e-11f;
  float t = x2 * inv_var;
  float p = c[9];
  for (int i = 8; i >= 0; --i) p = p * t + c[i];
  return p;
}

INLINE float rfilter_gaussian(float x, float stddev) {
  float inv_var = 1.0f / (stddev * stddev);
  float radius = 4.0f * stddev;
  return max(gaussian_remez(x * x, inv_var) - gaussian_remez(radius * radius, inv_var), 0.0f);
}

// mitchell.cpp (Mitchell & Netravali 1988, eq. 8): the cubic family with parameters B and C,
// radius 2. catmullrom.cpp is the member B = 0, C = 1/2.
INLINE float rfilter_mitchell(float x, float b, float c) {
  x = abs(x);
  float x2 = x * x;
  float x3 = x2 * x;
  float inner =
      (12.0f - 9.0f * b - 6.0f * c) * x3 + (-18.0f + 12.0f * b + 6.0f * c) * x2 + (6.0f - 2.0f * b);
  float outer = (-b - 6.0f * c) * x3 + (6.0f * b + 30.0f * c) * x2 + (-12.0f * b - 48.0f * c) * x +
                (8.0f * b + 24.0f * c);
  return x < 2.0f ? (1.0f / 6.0f) * (x < 1.0f ? inner : outer) : 0.0f;
}

// lanczos.cpp: the sinc windowed by the sinc of `lobes` times its width, radius = lobes;
// 1 below float epsilon.
INLINE float rfilter_lanczos(float x, float lobes) {
  x = abs(x);
  if (x < 5.9604645e-8f) return 1.0f;  // dr::Epsilon<float> = 2^-24
  if (x > lobes) return 0.0f;
  float x1 = PI * x;
  float x2 = x1 / lobes;
  return (sin(x1) * sin(x2)) / (x1 * x2);
}

// The filter `type` (RFILTER_*, all but the box, which Mitsuba never tabulates) at x. params:
// gaussian (stddev), tent (radius), mitchell (B, C), lanczos (lobes).
INLINE float rfilter_eval(uint type, vec4 params, float x) {
  if (type == RFILTER_GAUSSIAN) return rfilter_gaussian(x, params.x);
  if (type == RFILTER_TENT) return rfilter_tent(x, params.x);
  if (type == RFILTER_MITCHELL) return rfilter_mitchell(x, params.x, params.y);
  if (type == RFILTER_CATMULLROM) return rfilter_mitchell(x, 0.0f, 0.5f);
  return rfilter_lanczos(x, params.x);
}

// Entry i of Mitsuba's table: f(radius i / 31), and 0 for i >= 31 (init_discretization).
INLINE float rfilter_table_entry(uint type, vec4 params, float radius, uint i) {
  if (i >= FILTER_RESOLUTION) return 0.0f;
  return rfilter_eval(type, params, (radius * float(i)) / float(FILTER_RESOLUTION));
}

// Mass of |f_d| before bin k of an axis (core/film.h: bins in order of x, entry 30 - j for
// j < 31, else j - 31, each of width radius / 31).
INLINE float filter_cdf_entry(const vec4 table[8], float radius, uint k) {
  float sum = 0.0f;
  for (uint j = 0u; j < k; ++j) {
    uint i = j < FILTER_RESOLUTION ? FILTER_RESOLUTION - 1u - j : j - FILTER_RESOLUTION;
    sum += abs(table[i >> 2u][i & 3u]);
  }
  return sum * (radius / float(FILTER_RESOLUTION));
}

TR_NAMESPACE_END

#endif
