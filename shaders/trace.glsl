// Ray queries of the ray-generation shaders, from one call site of traceRayEXT: a closest-hit
// query (hit group by instance, the miss shader writes miss_hit()) or an occlusion query
// (terminate on first hit, no closest-hit shader: the payload keeps the shape set here, 0,
// unless the miss shader runs). The driver saves and restores the caller's live state around
// each call site; one site for both queries made the all-features path kernel a third faster
// (BENCHMARKS.md). Geometry is opaque except alpha-tested meshes, whose any-hit shader
// (shaders/alpha.rahit) drops cut-away hits for both kinds of rays; Mitsuba `mask` is a null
// BSDF lobe handled by the core, and its shadow rays treat masked surfaces as opaque.
#ifndef TWINRAY_SHADERS_TRACE_GLSL
#define TWINRAY_SHADERS_TRACE_GLSL

#include "core/bindings.h"
#include "core/hit.h"
#include "core/ray.h"

layout(set = 0, binding = BINDING_TLAS) uniform accelerationStructureEXT g_tlas;

layout(location = 0) rayPayloadEXT Hit g_hit;

// The SBT record stride is 0: every geometry of a TLAS instance uses the instance's hit group.
// Rays are opaque unless the scene alpha-tests (a specialization constant: the flag folds).
const uint TRACE_FLAGS = TR_HAS_MATERIAL_FLAG(MATERIAL_ALPHA_TESTED) ? gl_RayFlagsNoneEXT : gl_RayFlagsOpaqueEXT;
const uint OCCLUSION_FLAGS = gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT;

// The closest hit of r, or for an occlusion query a Hit whose shape is NO_INDEX exactly when
// nothing blocks r.
Hit trace(Ray r, bool occlusion) {
  g_hit.shape = 0u;
  traceRayEXT(g_tlas, occlusion ? TRACE_FLAGS | OCCLUSION_FLAGS : TRACE_FLAGS, 0xff, 0, 0, 0, r.o,
              r.tmin, r.d, r.tmax, 0);
  return g_hit;
}

#endif
