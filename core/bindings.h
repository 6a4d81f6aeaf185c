// Descriptor bindings of the Vulkan backend, shared by the host (gpu_backend/) and the
// shaders (shaders/), after NVIDIA's vk_raytracing_tutorial host_device.h. Set 0 holds the
// scene: one std430 storage buffer per SceneBuffers vector, in this order.
#ifndef TWINRAY_CORE_BINDINGS_H
#define TWINRAY_CORE_BINDINGS_H

#define BINDING_TLAS 0
#define BINDING_GLOBALS 1
#define BINDING_MATERIALS 2
#define BINDING_TEXTURES 3
#define BINDING_TEXELS 4
#define BINDING_EMITTERS 5
#define BINDING_ALIAS 6
#define BINDING_SHAPES 7
#define BINDING_INSTANCES 8
#define BINDING_POSITIONS 9
#define BINDING_NORMALS 10
#define BINDING_UVS 11
#define BINDING_INDICES 12
#define BINDING_ACCUMULATION 13
#define BINDING_GEOMETRY_SHAPES 14  // gpu_backend/scene_accel.h: TLAS geometry -> shape
#define BINDING_AOVS 15             // Mitsuba `aov`: per pixel and output variable, one PixelBatch
#define BINDING_ATTRIBUTES 16       // mesh attributes (core/texture.h, eval_mesh_attribute)
#define BINDING_SOBOL 17  // `sobol`: its matrices' nibble table (core/samplers/sobol_matrices.h)
#define BINDING_LIGHT_NODES 18  // emitter selection by light BVH (core/light_bvh.h)
#define BINDING_COUNT 19

#endif
