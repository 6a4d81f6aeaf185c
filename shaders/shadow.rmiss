// Occlusion query that hit nothing: the segment is unoccluded.
#version 460
#extension GL_EXT_ray_tracing : require

layout(location = 1) rayPayloadInEXT uint g_unoccluded;

void main() { g_unoccluded = 1u; }
