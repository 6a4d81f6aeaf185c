// Where a pixel's samples land on the film, so that each pixel converges to exactly the value
// Mitsuba 3.8's hdrfilm develops (scalar variants, the ones the references are rendered with).
//
// What Mitsuba computes (v3.8.0 sources):
//  - src/render/integrator.cpp (SamplingIntegrator::render, render_block, render_sample):
//    every pixel of the crop window gets spp samples at pixel + U[0,1)^2; with sample_border
//    the window is widened by the filter's border_size() on each side. The samples are thus
//    uniform over a rectangle S (Camera.sample_min/max).
//  - src/render/imageblock.cpp (ImageBlock::put, scalar path): a sample at p adds
//    f_d(c_x - p_x) f_d(c_y - p_y) (R, G, B, 1) to every pixel, centre c, within the filter
//    radius, where f_d is eval_discretized: the table of include/mitsuba/core/rfilter.h, a
//    step function (f(r i / 31) on |x| in [r i / 31, r (i + 1) / 31), core/rfilter.h), not the
//    continuous filter. Film::put_block (accumulate_2d) drops what lands outside the crop
//    window. The box filter (radius 0.5, ImageBlock's constructor) is no filter: each sample
//    counts once, in its own pixel.
//  - src/films/hdrfilm.cpp (develop / bitmap): RGB is divided by the weight channel W.
// As spp grows, pixel c therefore converges to
//     I(c) = integral_S f_d(c - x) L(x) dx / integral_S f_d(c - x) dx,
// f_d(x) = f_d(x_x) f_d(x_y): the footprint is truncated to S and renormalized over the part
// inside (at the film border), and negative lobes enter numerator and denominator with their
// sign.
//
// The estimator here (filter importance sampling, pbrt-v4 §8.8.2, made signed): pixel c draws
// x from q(x) proportional to |f_d(c - x)| on S, per axis (S is a rectangle and f_d separable),
// and gives the sample the sign s = sign f_d(c - x). The backends keep positive and negative
// samples apart and develop sum(s L) / sum(s) (render/film_moments.h), Mitsuba's division by
// W. Since E[s L] / E[s] = integral_S f_d L / integral_S f_d, the estimate converges to I(c).
// For filters without negative lobes s = 1: the plain mean, whose per-sample variance
// integral_S f_d (L - I)^2 / integral_S f_d is what Mitsuba's `moment` integrator records for
// the pixel. With negative lobes no per-pixel estimator does as well: with n samples of
// per-sample noise sigma^2 its variance is at least (integral |f_d| / integral f_d)^2
// sigma^2 / n (Cauchy-Schwarz on sum w_i^2 with w = f_d / q), while Mitsuba's splatting
// reuses each sample in every pixel it reaches.
#ifndef TWINRAY_CORE_FILM_H
#define TWINRAY_CORE_FILM_H

#include "core/rfilter.h"

TR_NAMESPACE_BEGIN

INLINE float filter_table_value(Camera c, uint i) { return c.filter_table[i >> 2u][i & 3u]; }

// Bin k of one axis (k < 31: the negative side, table entry 30 - k; else entry k - 31): its
// interval [a, a + h) of offsets x - c and its table entry.
INLINE uint filter_bin_entry(uint k) {
  return k < FILTER_RESOLUTION ? FILTER_RESOLUTION - 1u - k : k - FILTER_RESOLUTION;
}

INLINE float filter_bin_start(uint k, float h) {
  return k < FILTER_RESOLUTION ? -float(FILTER_RESOLUTION - k) * h
                               : float(k - FILTER_RESOLUTION) * h;
}

// |f_d| times the length of bin k clipped to [lo, hi).
INLINE float filter_bin_mass(Camera c, uint k, float lo, float hi) {
  float h = c.filter_radius / float(FILTER_RESOLUTION);
  float a = filter_bin_start(k, h);
  float len = max(min(a + h, hi) - max(a, lo), 0.0f);
  return abs(filter_table_value(c, filter_bin_entry(k))) * len;
}

// One axis: an offset x in [lo, hi) from the pixel centre with density proportional to
// |f_d(x)| there, and the sign of f_d(x). u picks the bin (the last one with mass whose
// cumulative start is <= u times the total, so rounding never picks an empty bin), then x is
// uniform within the bin's clipped interval.
INLINE float sample_filter_axis(Camera c, float u, float lo, float hi, OUT(float) sign) {
  const uint bins = 2u * FILTER_RESOLUTION;
  float total = 0.0f;
  for (uint k = 0u; k < bins; ++k) total += filter_bin_mass(c, k, lo, hi);
  float target = u * total;
  float before = 0.0f;
  uint chosen = 0u;
  float chosen_before = 0.0f;
  float chosen_mass = 0.0f;
  for (uint k = 0u; k < bins; ++k) {
    float mass = filter_bin_mass(c, k, lo, hi);
    if (mass > 0.0f && target >= before) {
      chosen = k;
      chosen_before = before;
      chosen_mass = mass;
    }
    before += mass;
  }
  float h = c.filter_radius / float(FILTER_RESOLUTION);
  float a = max(filter_bin_start(chosen, h), lo);
  float b = min(filter_bin_start(chosen, h) + h, hi);
  float v = clamp((target - chosen_before) / chosen_mass, 0.0f, ONE_MINUS_EPSILON);
  sign = filter_table_value(c, filter_bin_entry(chosen)) < 0.0f ? -1.0f : 1.0f;
  return a + v * (b - a);
}

// Position on the film (full-film pixels) of a sample of `pixel` (crop-window pixels) and its
// sign in the pixel's self-normalized estimate.
INLINE vec2 sample_film_position(Camera c, uvec2 pixel, vec2 u, OUT(float) sign) {
  vec2 center = c.crop_offset + vec2(pixel) + vec2(0.5f);
  if (c.rfilter == RFILTER_BOX) {
    sign = 1.0f;
    return center + (u - vec2(0.5f));
  }
  vec2 lo = c.sample_min - center;
  vec2 hi = c.sample_max - center;
  float sx;
  float sy;
  float x = sample_filter_axis(c, u.x, lo.x, hi.x, sx);
  float y = sample_filter_axis(c, u.y, lo.y, hi.y, sy);
  sign = sx * sy;
  return center + vec2(x, y);
}

TR_NAMESPACE_END

#endif
