// core/scene_access.h over the std430 storage buffers of set 0 (bindings in core/bindings.h).
#ifndef TWINRAY_SHADERS_SCENE_ACCESS_GLSL
#define TWINRAY_SHADERS_SCENE_ACCESS_GLSL

#include "shaders/features.glsl"
#include "core/bindings.h"
#include "core/scene_access.h"

layout(std430, set = 0, binding = BINDING_GLOBALS) readonly buffer GlobalsBuffer { SceneGlobals g_globals; };
layout(std430, set = 0, binding = BINDING_MATERIALS) readonly buffer MaterialBuffer { Material g_materials[]; };
layout(std430, set = 0, binding = BINDING_TEXTURES) readonly buffer TextureBuffer { Texture g_textures[]; };
layout(std430, set = 0, binding = BINDING_TEXELS) readonly buffer TexelBuffer { vec4 g_texels[]; };
layout(std430, set = 0, binding = BINDING_EMITTERS) readonly buffer EmitterBuffer { Emitter g_emitters[]; };
layout(std430, set = 0, binding = BINDING_ALIAS) readonly buffer AliasBuffer { AliasEntry g_alias[]; };
layout(std430, set = 0, binding = BINDING_LIGHT_NODES) readonly buffer LightNodeBuffer { LightNode g_light_nodes[]; };
layout(std430, set = 0, binding = BINDING_SHAPES) readonly buffer ShapeBuffer { Shape g_shapes[]; };
layout(std430, set = 0, binding = BINDING_INSTANCES) readonly buffer InstanceBuffer { Instance g_instances[]; };
layout(std430, set = 0, binding = BINDING_POSITIONS) readonly buffer PositionBuffer { vec4 g_positions[]; };
layout(std430, set = 0, binding = BINDING_NORMALS) readonly buffer NormalBuffer { vec4 g_normals[]; };
layout(std430, set = 0, binding = BINDING_UVS) readonly buffer UvBuffer { vec2 g_uvs[]; };
layout(std430, set = 0, binding = BINDING_INDICES) readonly buffer IndexBuffer { uint g_indices[]; };
layout(std430, set = 0, binding = BINDING_ATTRIBUTES) readonly buffer AttributeBuffer { uint g_attributes[]; };
layout(std430, set = 0, binding = BINDING_SOBOL) readonly buffer SobolBuffer { uvec2 g_sobol_nibbles[]; };

SceneGlobals scene_globals() { return g_globals; }
Material scene_material(uint i) { return g_materials[i]; }
Texture scene_texture(uint i) { return g_textures[i]; }
vec4 scene_texel(uint i) { return g_texels[i]; }
Emitter scene_emitter(uint i) { return g_emitters[i]; }
AliasEntry scene_alias(uint i) { return g_alias[i]; }
LightNode scene_light_node(uint i) { return g_light_nodes[i]; }
Shape scene_shape(uint i) { return g_shapes[i]; }
Instance scene_instance(uint i) { return g_instances[i]; }
vec3 scene_position(uint v) { return g_positions[v].xyz; }
vec3 scene_normal(uint v) { return g_normals[v].xyz; }
vec2 scene_uv(uint v) { return g_uvs[v]; }
uint scene_index(uint i) { return g_indices[i]; }
uint scene_attribute(uint i) { return g_attributes[i]; }
uvec2 scene_sobol_nibble(uint i) { return g_sobol_nibbles[i]; }
float scene_filter_table(uint i) { return g_globals.camera.filter_table[i >> 2u][i & 3u]; }
uint scene_aov_type(uint i) { return g_globals.integrator.aov_types[i >> 2u][i & 3u]; }
float scene_filter_cdf(uint k) { return g_globals.camera.filter_cdf[k >> 2u][k & 3u]; }

#endif
