// core/scene_access.h over the host vectors of the bound SceneBuffers.
#include "core/scene_access.h"

#include "cpu_backend/bound_scene.h"

namespace tr {
namespace {
const SceneBuffers* g_buffers = nullptr;
}

void bind_scene_buffers(const SceneBuffers* buffers) { g_buffers = buffers; }

const SceneGlobals& scene_globals() { return g_buffers->globals; }
const Material& scene_material(uint i) { return g_buffers->materials[i]; }
const Texture& scene_texture(uint i) { return g_buffers->textures[i]; }
vec4 scene_texel(uint i) { return g_buffers->texels[i]; }
const Emitter& scene_emitter(uint i) { return g_buffers->emitters[i]; }
AliasEntry scene_alias(uint i) { return g_buffers->alias[i]; }
const LightNode& scene_light_node(uint i) { return g_buffers->light_nodes[i]; }
const Shape& scene_shape(uint i) { return g_buffers->shapes[i]; }
const Instance& scene_instance(uint i) { return g_buffers->instances[i]; }
vec3 scene_position(uint v) { return vec3(g_buffers->positions[v]); }
vec3 scene_normal(uint v) { return vec3(g_buffers->normals[v]); }
vec2 scene_uv(uint v) { return g_buffers->uvs[v]; }
uint scene_index(uint i) { return g_buffers->indices[i]; }
uint scene_attribute(uint i) { return g_buffers->attributes[i]; }
float scene_filter_table(uint i) { return g_buffers->globals.camera.filter_table[i >> 2u][i & 3u]; }
uint scene_aov_type(uint i) { return g_buffers->globals.integrator.aov_types[i >> 2u][i & 3u]; }
float scene_filter_cdf(uint k) { return g_buffers->globals.camera.filter_cdf[k >> 2u][k & 3u]; }

}  // namespace tr
