// The ray-generation shader's per-dispatch parameters and per-pixel batch output.
#ifndef TWINRAY_SHADERS_ACCUMULATE_GLSL
#define TWINRAY_SHADERS_ACCUMULATE_GLSL

#include "core/bindings.h"
#include "shaders/batch.h"

layout(push_constant) uniform BatchParamsBlock { BatchParams g_params; };

layout(std430, set = 0, binding = BINDING_ACCUMULATION) writeonly buffer BatchBuffer {
  PixelBatch g_batches[];
};

// Mitsuba `aov` (core/integrators/aov.h): record `first + i` holds output variable i's batch.
layout(std430, set = 0, binding = BINDING_AOVS) buffer AovBatchBuffer {
  PixelBatch g_aov_batches[];
};

// Welford's update (Welford 1962; Knuth TAOCP vol. 2, §4.2.2) after the n-th sample x.
void welford_add(inout vec3 mean, inout vec3 m2, uint n, vec3 x) {
  vec3 delta = x - mean;
  mean += delta / float(n);
  m2 += delta * (x - mean);
}

void aov_batches_clear(uint first, uint count) {
  for (uint i = 0u; i < count; ++i) {
    g_aov_batches[first + i].mean = vec3(0.0f);
    g_aov_batches[first + i].rejected = 0u;
    g_aov_batches[first + i].m2 = vec3(0.0f);
    g_aov_batches[first + i].rays = 0u;
    g_aov_batches[first + i].mean_negative = vec3(0.0f);
    g_aov_batches[first + i].negative = 0u;
    g_aov_batches[first + i].m2_negative = vec3(0.0f);
    g_aov_batches[first + i].pad0 = 0u;
  }
}

// Adds variable i's value x as the n-th positive or negative sample of the batch.
void aov_batch_add(uint record, bool negative, uint n, vec3 x) {
  if (negative) {
    vec3 mean = g_aov_batches[record].mean_negative;
    vec3 m2 = g_aov_batches[record].m2_negative;
    welford_add(mean, m2, n, x);
    g_aov_batches[record].mean_negative = mean;
    g_aov_batches[record].m2_negative = m2;
    g_aov_batches[record].negative = n;
  } else {
    vec3 mean = g_aov_batches[record].mean;
    vec3 m2 = g_aov_batches[record].m2;
    welford_add(mean, m2, n, x);
    g_aov_batches[record].mean = mean;
    g_aov_batches[record].m2 = m2;
  }
}

#endif
