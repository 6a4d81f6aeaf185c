// A query that hit nothing (shaders/trace.glsl): for an occlusion query, its answer that
// nothing blocks the ray.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "core/hit.h"

layout(location = 0) rayPayloadInEXT Hit g_hit;

void main() { g_hit = miss_hit(); }
