// Records shared by the ray-generation shader and the host (gpu_backend/render_gpu.cpp):
// the per-dispatch parameters (push constants) and the per-pixel result of one batch.
#ifndef TWINRAY_SHADERS_BATCH_H
#define TWINRAY_SHADERS_BATCH_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

struct BatchParams {
  uint first_sample;  // global sample index of the batch's first sample
  uint sample_count;  // samples per pixel in this batch
  uint seed;
  uint pad0;
};

// One pixel's batch: mean and sum of squared deviations M2 of the batch's positive and of its
// negative samples (core/film.h; Welford 1962, in float), how many were negative, the samples
// rejected as NaN/Inf (counted as zero radiance) and the rays traced. The host merges batches
// in double (render/film_moments.h).
struct PixelBatch {
  vec3 mean;
  uint rejected;
  vec3 m2;
  uint rays;
  vec3 mean_negative;
  uint negative;
  vec3 m2_negative;
  uint pad0;
};

TR_NAMESPACE_END

#endif
