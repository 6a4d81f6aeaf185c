// Closest-hit query that hit nothing.
#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require

#include "core/hit.h"

layout(location = 0) rayPayloadInEXT Hit g_hit;

void main() { g_hit = miss_hit(); }
