// Queries of the compute shader tests/bsdf_gpu/bsdf_probe.comp: one core/ entry point at given
// arguments per query, one result per query (std430, shared by the host and the shader).
#ifndef TWINRAY_TESTS_BSDF_GPU_PROBE_H
#define TWINRAY_TESTS_BSDF_GPU_PROBE_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// ProbeQuery.op: arguments (a, b, c) -> result fields.
const uint PROBE_WARP_DIRECTION = 0u;      // subject = warp; a.xy = u, a.z = parameter -> wo
const uint PROBE_WARP_DIRECTION_PDF = 1u;  // subject = warp; a.xyz = w, a.w = parameter -> pdf
const uint PROBE_WARP_POINT = 2u;          // subject = warp; a.xy = u -> wo.xy
const uint PROBE_WARP_POINT_PDF = 3u;      // subject = warp; a.xy = point -> pdf
const uint PROBE_MICROFACET_SAMPLE = 4u;   // subject = PROBE_MICROFACET_*; a.xy = alphas,
                                           // b.xyz = wi, c.xy = u -> wo (the normal)
const uint PROBE_MICROFACET_PDF = 5u;      // as above with c.xyz = m -> pdf
const uint PROBE_BSDF_SAMPLE = 6u;         // subject = material; a.xy = uv, a.z = u1, b.xyz = wi,
                                           // c.xy = u2 -> wo, pdf, value = weight, eta, lobe
const uint PROBE_BSDF_PDF = 7u;            // as above with c.xyz = wo -> pdf
const uint PROBE_BSDF_EVAL = 8u;           // as above with c.xyz = wo -> value = f |cos theta_o|

// Warps (the order of tr::bsdf_suite::Warp in tests/bsdf/core_calls.h).
const uint PROBE_WARP_COSINE_HEMISPHERE = 0u;
const uint PROBE_WARP_UNIFORM_SPHERE = 1u;
const uint PROBE_WARP_UNIFORM_HEMISPHERE = 2u;
const uint PROBE_WARP_UNIFORM_CONE = 3u;
const uint PROBE_WARP_DISK_CONCENTRIC = 4u;
const uint PROBE_WARP_TRIANGLE = 5u;

// Microfacet distribution flags.
const uint PROBE_MICROFACET_BECKMANN = 1u;
const uint PROBE_MICROFACET_VISIBLE = 2u;

struct ProbeQuery {
  uint op;
  uint subject;
  uint pad0;
  uint pad1;
  vec4 a;
  vec4 b;
  vec4 c;
};

struct ProbeResult {
  vec4 wo_pdf;     // sampled direction (or point) and density
  vec4 value_eta;  // sample weight or eval, and the sample's relative IOR
  uint lobe;
  uint pad0;
  uint pad1;
  uint pad2;
};

TR_NAMESPACE_END

#endif
