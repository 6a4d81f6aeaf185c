// Closest hit of triangles and analytic shapes alike: reports the hit to the core.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "core/hit.h"
#include "shaders/geometry.glsl"

layout(location = 0) rayPayloadInEXT Hit g_hit;
// Triangles: the built-in barycentrics (b1, b2); analytic shapes: zero (shaders/shape.rint).
hitAttributeEXT vec2 g_barycentrics;

void main() {
  g_hit.instance = gl_InstanceCustomIndexEXT;
  g_hit.shape = current_shape();
  g_hit.primitive = gl_PrimitiveID;
  g_hit.t = gl_HitTEXT;
  g_hit.barycentrics = g_barycentrics;
  g_hit.pad0 = 0u;
  g_hit.pad1 = 0u;
}
