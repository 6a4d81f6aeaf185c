// Ray queries of the ray-generation shader: closest hit (payload 0, hit group by instance,
// miss shader 0) and occlusion (payload 1, terminate on first hit, no closest-hit shader,
// miss shader 1 marks the ray unoccluded). Geometry is opaque except alpha-tested meshes, whose
// any-hit shader (shaders/alpha.rahit) drops cut-away hits for both kinds of rays; Mitsuba
// `mask` is a null BSDF lobe handled by the core, and its shadow rays treat masked surfaces
// as opaque.
#ifndef TWINRAY_SHADERS_TRACE_GLSL
#define TWINRAY_SHADERS_TRACE_GLSL

#include "core/bindings.h"
#include "core/hit.h"
#include "core/ray.h"

layout(set = 0, binding = BINDING_TLAS) uniform accelerationStructureEXT g_tlas;

layout(location = 0) rayPayloadEXT Hit g_hit;
layout(location = 1) rayPayloadEXT uint g_unoccluded;

// The SBT record stride is 0: every geometry of a TLAS instance uses the instance's hit group.
// Rays are opaque unless the scene alpha-tests (a specialization constant: the flag folds).
const uint TRACE_FLAGS = TR_HAS_MATERIAL_FLAG(MATERIAL_ALPHA_TESTED) ? gl_RayFlagsNoneEXT : gl_RayFlagsOpaqueEXT;

Hit trace_closest(Ray r) {
  traceRayEXT(g_tlas, TRACE_FLAGS, 0xff, 0, 0, 0, r.o, r.tmin, r.d, r.tmax, 0);
  return g_hit;
}

bool trace_unoccluded(Ray r) {
  g_unoccluded = 0u;
  traceRayEXT(g_tlas,
              TRACE_FLAGS | gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT,
              0xff, 0, 0, 1, r.o, r.tmin, r.d, r.tmax, 1);
  return g_unoccluded != 0u;
}

#endif
