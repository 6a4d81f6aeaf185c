// The shape a hit or intersection-shader invocation belongs to, through the geometry -> shape
// table of gpu_backend/scene_accel.h.
#ifndef TWINRAY_SHADERS_GEOMETRY_GLSL
#define TWINRAY_SHADERS_GEOMETRY_GLSL

#include "core/bindings.h"

layout(std430, set = 0, binding = BINDING_GEOMETRY_SHAPES) readonly buffer GeometryShapeBuffer {
  uint g_geometry_shapes[];
};

uint current_shape() { return g_geometry_shapes[g_geometry_shapes[gl_InstanceID] + gl_GeometryIndexEXT]; }

#endif
