// The GLSL build of core/'s warps, microfacet samplers and BSDFs, one query per invocation
// (tests/bsdf_gpu/probe.h): what the BSDF validation suite needs to validate the shader build
// of the math. Specialized per family through shaders/features.glsl, like the renderer.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shaders/scene_access.glsl"
#include "core/bsdf.h"
#include "core/microfacet.h"
#include "core/warp.h"
#include "tests/bsdf_gpu/probe.h"

layout(local_size_x = 64) in;

// 1: the deliberately broken variant: every smooth BSDF density, sampled or evaluated, is off by
// a factor |cos theta_o| (the sampled weight follows it, so only the chi-square can tell).
// (An id past shaders/features.glsl's, which grow from 0.)
layout(constant_id = 100) const uint SPEC_PDF_OFF_BY_COSINE = 0u;

layout(std430, set = 1, binding = 0) readonly buffer QueryBuffer { ProbeQuery g_queries[]; };
layout(std430, set = 1, binding = 1) writeonly buffer ResultBuffer { ProbeResult g_results[]; };
layout(push_constant) uniform ProbeParams {
  uint g_first;
  uint g_count;
};

ProbeResult probe_result(vec3 wo, float pdf, vec3 value, float eta, uint lobe) {
  ProbeResult r;
  r.wo_pdf = vec4(wo, pdf);
  r.value_eta = vec4(value, eta);
  r.lobe = lobe;
  r.pad0 = 0u;
  r.pad1 = 0u;
  r.pad2 = 0u;
  return r;
}

ProbeResult probe_pdf(float pdf) { return probe_result(vec3(0.0f), pdf, vec3(0.0f), 1.0f, 0u); }

vec3 warp_direction(uint warp, float parameter, vec2 u) {
  switch (warp) {
    case PROBE_WARP_COSINE_HEMISPHERE:
      return square_to_cosine_hemisphere(u);
    case PROBE_WARP_UNIFORM_SPHERE:
      return square_to_uniform_sphere(u);
    case PROBE_WARP_UNIFORM_HEMISPHERE:
      return square_to_uniform_hemisphere(u);
    default:
      return square_to_uniform_cone(u, parameter);
  }
}

float warp_direction_pdf(uint warp, float parameter, vec3 w) {
  switch (warp) {
    case PROBE_WARP_COSINE_HEMISPHERE:
      return square_to_cosine_hemisphere_pdf(w);
    case PROBE_WARP_UNIFORM_SPHERE:
      return square_to_uniform_sphere_pdf(w);
    case PROBE_WARP_UNIFORM_HEMISPHERE:
      return square_to_uniform_hemisphere_pdf(w);
    default:
      return square_to_uniform_cone_pdf(w, parameter);
  }
}

Microfacet probe_microfacet(ProbeQuery q) {
  return microfacet_make((q.subject & PROBE_MICROFACET_BECKMANN) != 0u, q.a.x, q.a.y,
                         (q.subject & PROBE_MICROFACET_VISIBLE) != 0u);
}

ProbeResult probe_bsdf_sample(ProbeQuery q) {
  BsdfSample s = bsdf_sample(scene_material(q.subject), q.a.xy, q.b.xyz, q.a.z, q.c.xy);
  if (SPEC_PDF_OFF_BY_COSINE != 0u && (s.lobe & BSDF_SMOOTH) != 0u) {
    float cos_theta = abs(s.wo.z);
    s.pdf *= cos_theta;
    s.weight = cos_theta > 0.0f ? s.weight / cos_theta : vec3(0.0f);
    if (cos_theta == 0.0f) s.pdf = 0.0f;
  }
  return probe_result(s.wo, s.pdf, s.weight, s.eta, s.lobe);
}

ProbeResult probe(ProbeQuery q) {
  switch (q.op) {
    case PROBE_WARP_DIRECTION:
      return probe_result(warp_direction(q.subject, q.a.z, q.a.xy), 0.0f, vec3(0.0f), 1.0f, 0u);
    case PROBE_WARP_DIRECTION_PDF:
      return probe_pdf(warp_direction_pdf(q.subject, q.a.w, q.a.xyz));
    case PROBE_WARP_POINT: {
      vec2 p = q.subject == PROBE_WARP_TRIANGLE ? square_to_uniform_triangle(q.a.xy)
                                                : square_to_uniform_disk_concentric(q.a.xy);
      return probe_result(vec3(p, 0.0f), 0.0f, vec3(0.0f), 1.0f, 0u);
    }
    case PROBE_WARP_POINT_PDF:
      return probe_pdf(square_to_uniform_disk_concentric_pdf(q.a.xy));
    case PROBE_MICROFACET_SAMPLE:
      return probe_result(microfacet_sample(probe_microfacet(q), q.b.xyz, q.c.xy), 0.0f,
                          vec3(0.0f), 1.0f, 0u);
    case PROBE_MICROFACET_PDF:
      return probe_pdf(microfacet_pdf(probe_microfacet(q), q.b.xyz, q.c.xyz));
    case PROBE_BSDF_SAMPLE:
      return probe_bsdf_sample(q);
    case PROBE_BSDF_PDF: {
      float pdf = bsdf_pdf(scene_material(q.subject), q.a.xy, q.b.xyz, q.c.xyz);
      return probe_pdf(SPEC_PDF_OFF_BY_COSINE != 0u ? pdf * abs(q.c.z) : pdf);
    }
    default:
      return probe_result(vec3(0.0f), 0.0f,
                          bsdf_eval(scene_material(q.subject), q.a.xy, q.b.xyz, q.c.xyz), 1.0f,
                          0u);
  }
}

void main() {
  uint i = g_first + gl_GlobalInvocationID.x;
  if (i < g_count) g_results[i] = probe(g_queries[i]);
}
