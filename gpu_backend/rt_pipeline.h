// The ray-tracing pipeline and its shader binding table.
//   groups: 0 … R-1 the R ray-generation shaders | R miss (closest query) | R+1 miss
//           (occlusion query) | R+2 triangle hit group (closest hit; any-hit
//           shaders/alpha.rahit only in a scene that alpha-tests) | R+3 procedural hit group
//           (intersection + closest hit), matching HIT_GROUP_TRIANGLES / HIT_GROUP_PROCEDURAL.
// Set 0 holds the bindings of core/bindings.h; the push constants are a BatchParams; every
// stage is specialized with the scene's feature masks (shaders/features.glsl).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gpu_backend/vk_device.h"
#include "gpu_backend/vulkan_api.h"
#include "scenes/scene_features.h"

namespace tr {

struct Spirv {
  const uint32_t* code;
  size_t bytes;
};

class RayTracingPipeline {
 public:
  // raygens: the ray-generation shaders (shaders/raygen.rgen and shaders/aov.rgen for
  // renders); each dispatch runs one of them.
  RayTracingPipeline(VulkanDevice& device, const std::vector<Spirv>& raygens,
                     const SceneFeatures& features);
  ~RayTracingPipeline();
  RayTracingPipeline(const RayTracingPipeline&) = delete;
  RayTracingPipeline& operator=(const RayTracingPipeline&) = delete;

  VkDescriptorSetLayout set_layout() const { return set_layout_; }
  VkPipelineLayout layout() const { return layout_; }
  VkPipeline pipeline() const { return pipeline_; }

  // The stack (bytes) the driver reserves for ray-generation shader `raygen`: its live state
  // kept across traceRayEXT, spills and local arrays (vkGetRayTracingShaderGroupStackSizeKHR).
  VkDeviceSize raygen_stack_size(uint32_t raygen) const;

  // vkCmdBindPipeline + vkCmdTraceRaysKHR of ray-generation shader `raygen` over
  // width x height.
  void trace(VkCommandBuffer cmd, uint32_t raygen, uint32_t width, uint32_t height) const;

 private:
  void destroy();
  void build_sbt();
  VulkanDevice& device_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  Buffer sbt_;
  std::vector<VkStridedDeviceAddressRegionKHR> raygens_;
  VkStridedDeviceAddressRegionKHR miss_{}, hit_{}, callable_{};
};

}  // namespace tr
