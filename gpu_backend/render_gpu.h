// The Vulkan ray-tracing backend's entry points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "render/render.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "scenes/scene_features.h"

namespace tr {

// Renders `scene` with the core's path integrator in ray-tracing shaders. stats.seconds
// counts the acceleration-structure builds and the dispatches (as the CPU backend counts
// its BVH build and sampling), not Vulkan start-up or pipeline compilation. Throws GpuError
// (one line) when no usable device exists, naming what is missing and suggesting
// --backend cpu, and when the Vulkan validation layer (TWINRAY_VK_VALIDATION=1) reports an
// error.
RenderResult render_gpu(const Scene& scene, const RenderOptions& options);

// The same backend for progressive rendering (render/renderer.h); throws as render_gpu.
std::unique_ptr<Renderer> make_gpu_renderer(const Scene& scene, const RenderOptions& options);

// Knobs and timings of the GPU backend beyond RenderOptions, for tests and measurements.
struct GpuTuning {
  // The features the pipeline is specialized for; unset: the scene's own (scene_features),
  // all_features(): the all-features pipeline. They must cover the scene's.
  std::optional<SceneFeatures> features;
  // The ray-generation shaders' builds that keep their loops (SpirvBuilds::cpu) on every
  // device.
  bool keep_loops = false;
};

struct GpuTimings {
  double setup_seconds = 0.0;           // instance, device, buffers
  double pipeline_seconds = 0.0;        // ray-tracing pipeline creation (shader compilation)
  double build_seconds = 0.0;           // acceleration structures
  double render_seconds = 0.0;          // dispatches and batch merging
  double first_dispatch_seconds = 0.0;  // part of render_seconds; lavapipe compiles here
  uint32_t first_dispatch_spp = 0;
  uint64_t raygen_stack_bytes = 0;  // the path shader's (RayTracingPipeline::raygen_stack_size)
};

// A ray-generation shader as SPIR-V, in the build for GPUs and the one for CPU devices
// (lavapipe): the renderer's shaders keep their loops there (core/prelude.h UNROLL).
struct SpirvBuilds {
  const uint32_t* gpu;
  size_t gpu_bytes;
  const uint32_t* cpu;
  size_t cpu_bytes;
};

// A render's ray-generation shaders: the one that writes each pixel's PixelBatch
// (shaders/batch.h) and, for scenes with AOVs, the one that writes theirs, dispatched before it
// over the same samples (unset: the shader renders no AOVs; a scene with some is refused).
struct RaygenShader {
  SpirvBuilds pixels;
  std::optional<SpirvBuilds> aovs;
};

// shaders/raygen.rgen and shaders/aov.rgen, both builds.
RaygenShader renderer_raygen();

// A shader with one build for every device and no AOVs (the tests' probes).
inline RaygenShader one_raygen(const uint32_t* spirv, size_t bytes) {
  return RaygenShader{SpirvBuilds{spirv, bytes, spirv, bytes}, std::nullopt};
}

// render_gpu with another ray-generation shader writing the same PixelBatch records
// (shaders/batch.h); tests probe traversal with it.
RenderResult render_with_raygen(const Scene& scene, const RenderOptions& options,
                                const RaygenShader& raygen, const GpuTuning& tuning = GpuTuning(),
                                GpuTimings* timings = nullptr);

// `twinray devices`: lists every Vulkan device, whether it is usable and, if not, what it
// lacks. argv holds the arguments after `devices`. Returns 0 when at least one device is
// usable.
int devices_command(int argc, char** argv);

}  // namespace tr
