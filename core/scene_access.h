// Scene data access used by the shared light-transport code. Each backend defines these
// functions: the CPU backend over the host vectors of tr::SceneBuffers (cpu_backend/
// scene_access.cpp), the GPU backend over the std430 storage buffers of the same records
// (shaders/scene_access.glsl). Core code never touches scene memory any other way, so both
// backends read identical data through identical arithmetic.
#ifndef TWINRAY_CORE_SCENE_ACCESS_H
#define TWINRAY_CORE_SCENE_ACCESS_H

#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

REF(SceneGlobals) scene_globals();
REF(Material) scene_material(uint index);
REF(Texture) scene_texture(uint index);
vec4 scene_texel(uint index);
REF(Emitter) scene_emitter(uint index);
AliasEntry scene_alias(uint index);
REF(LightNode) scene_light_node(uint index);
REF(Shape) scene_shape(uint index);
REF(Instance) scene_instance(uint index);
vec3 scene_position(uint vertex);
vec3 scene_normal(uint vertex);
vec2 scene_uv(uint vertex);
uint scene_index(uint index);
// Word i of the mesh attribute buffer: per-mesh tables and the values as float bits
// (core/texture.h, eval_mesh_attribute).
uint scene_attribute(uint i);
// Entry i of the camera's reconstruction-filter table and k of its cumulative masses
// (Camera.filter_table, Camera.filter_cdf), read in place: an array copied into a shader's local
// memory and indexed there cost the GPU backend three quarters of its throughput.
float scene_filter_table(uint i);
float scene_filter_cdf(uint k);
// The type of the `aov` integrator's output variable i (Integrator.aov_types), read in place
// for the same reason.
uint scene_aov_type(uint i);
#ifndef __cplusplus
// Entry i of the Sobol matrices' nibble table (core/samplers/sobol_matrices.h), from a buffer: as
// a constant array indexed in the shader, lavapipe copied all of it into every invocation. The
// host reads the array in place (inline there).
uvec2 scene_sobol_nibble(uint i);
#endif

TR_NAMESPACE_END

#endif
