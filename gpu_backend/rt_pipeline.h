// The ray-tracing pipeline and its shader binding table.
//   groups: 0 raygen | 1 miss (closest query) | 2 miss (occlusion query)
//           3 triangle hit group (closest hit; any-hit shaders/alpha.rahit only in a scene
//           that alpha-tests) | 4 procedural hit group (intersection + closest hit), matching
//           HIT_GROUP_TRIANGLES / HIT_GROUP_PROCEDURAL.
// Set 0 holds the bindings of core/bindings.h; the push constants are a BatchParams; every
// stage is specialized with the scene's feature masks (shaders/features.glsl).
#pragma once

#include "gpu_backend/vk_device.h"
#include "gpu_backend/vulkan_api.h"
#include "scenes/scene_features.h"

namespace tr {

class RayTracingPipeline {
 public:
  // raygen: SPIR-V of the ray-generation shader (shaders/raygen.rgen for renders).
  RayTracingPipeline(VulkanDevice& device, const uint32_t* raygen, size_t raygen_bytes,
                     const SceneFeatures& features);
  ~RayTracingPipeline();
  RayTracingPipeline(const RayTracingPipeline&) = delete;
  RayTracingPipeline& operator=(const RayTracingPipeline&) = delete;

  VkDescriptorSetLayout set_layout() const { return set_layout_; }
  VkPipelineLayout layout() const { return layout_; }
  VkPipeline pipeline() const { return pipeline_; }

  // vkCmdBindPipeline + vkCmdTraceRaysKHR over width x height.
  void trace(VkCommandBuffer cmd, uint32_t width, uint32_t height) const;

 private:
  void destroy();
  void build_sbt();
  VulkanDevice& device_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  Buffer sbt_;
  VkStridedDeviceAddressRegionKHR raygen_{}, miss_{}, hit_{}, callable_{};
};

}  // namespace tr
