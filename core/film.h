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
#include "core/scene_access.h"

TR_NAMESPACE_BEGIN

// The bins of one axis, in order of x: bin k in [0, 62) covers [-r + k h, -r + (k + 1) h),
// h = r / 31, and holds table entry 30 - k (k < 31) or k - 31. Camera.filter_cdf[k] is the
// mass of |f_d| before bin k (k = 0 .. 62), filled by the loader (filter_cdf_entry). Both
// tables are the scene camera's (scene_filter_table, scene_filter_cdf).
INLINE uint filter_bin_entry(uint k) {
  return k < FILTER_RESOLUTION ? FILTER_RESOLUTION - 1u - k : k - FILTER_RESOLUTION;
}

// M(x): the mass of |f_d| on [-r, x], for the camera's filter of radius r.
INLINE float filter_cumulative(float r, float x) {
  float h = r / float(FILTER_RESOLUTION);
  float t = clamp(x, -r, r);
  uint k = min(uint((t + r) / h), 2u * FILTER_RESOLUTION - 1u);
  float start = -r + float(k) * h;
  return scene_filter_cdf(k) + abs(scene_filter_table(filter_bin_entry(k))) * max(t - start, 0.0f);
}

// One axis: an offset x in [lo, hi) from the pixel centre with density proportional to
// |f_d(x)| there, and the sign of f_d(x), by inverting M between M(lo) and M(hi): the bin is
// the last one whose start mass is <= the target (never an empty one), x is linear within it.
INLINE float sample_filter_axis(float r, float u, float lo, float hi, OUT(float) sign) {
  float m_lo = filter_cumulative(r, lo);
  float target = m_lo + u * (filter_cumulative(r, hi) - m_lo);
  const uint last = 2u * FILTER_RESOLUTION;
  uint k = 0u;
  for (uint step = 32u; step > 0u; step >>= 1u)
    if (k + step <= last && scene_filter_cdf(k + step) <= target) k += step;
  k = min(k, last - 1u);
  float h = r / float(FILTER_RESOLUTION);
  float start = -r + float(k) * h;
  float f = scene_filter_table(filter_bin_entry(k));
  float x = abs(f) > 0.0f ? start + (target - scene_filter_cdf(k)) / abs(f) : start;
  sign = f < 0.0f ? -1.0f : 1.0f;
  return clamp(x, max(start, lo), min(start + h, hi));
}

// Position on the film (full-film pixels) of a sample of `pixel` (crop-window pixels) and its
// sign in the pixel's self-normalized estimate; `c` is the scene's camera.
INLINE vec2 sample_film_position(IN(Camera) c, uvec2 pixel, vec2 u, OUT(float) sign) {
  vec2 center = c.crop_offset + vec2(pixel) + vec2(0.5f);
  if (c.rfilter == RFILTER_BOX) {
    sign = 1.0f;
    return center + (u - vec2(0.5f));
  }
  vec2 lo = c.sample_min - center;
  vec2 hi = c.sample_max - center;
  float sx;
  float sy;
  float x = sample_filter_axis(c.filter_radius, u.x, lo.x, hi.x, sx);
  float y = sample_filter_axis(c.filter_radius, u.y, lo.y, hi.y, sy);
  sign = sx * sy;
  return center + vec2(x, y);
}

TR_NAMESPACE_END

#endif
