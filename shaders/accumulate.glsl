// The ray-generation shader's per-dispatch parameters and per-pixel batch output.
#ifndef TWINRAY_SHADERS_ACCUMULATE_GLSL
#define TWINRAY_SHADERS_ACCUMULATE_GLSL

#include "core/bindings.h"
#include "shaders/batch.h"

layout(push_constant) uniform BatchParamsBlock { BatchParams g_params; };

layout(std430, set = 0, binding = BINDING_ACCUMULATION) writeonly buffer BatchBuffer {
  PixelBatch g_batches[];
};

// Welford's update (Welford 1962; Knuth TAOCP vol. 2, §4.2.2) after the n-th sample x.
void welford_add(inout vec3 mean, inout vec3 m2, uint n, vec3 x) {
  vec3 delta = x - mean;
  mean += delta / float(n);
  m2 += delta * (x - mean);
}

#endif
