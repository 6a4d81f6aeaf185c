// A scene on the device: one storage buffer per SceneBuffers vector at its binding of
// core/bindings.h, the acceleration structures, the geometry -> shape table, and the
// descriptor set binding them together with the per-pixel batch buffer.
#pragma once

#include <memory>
#include <vector>

#include "gpu_backend/scene_accel.h"
#include "gpu_backend/vk_device.h"
#include "scenes/scene.h"

namespace tr {

class GpuScene {
 public:
  // batches: the BINDING_ACCUMULATION buffer; aov_batches: the BINDING_AOVS buffer.
  GpuScene(VulkanDevice& device, const SceneBuffers& scene, VkDescriptorSetLayout layout,
           const Buffer& batches, const Buffer& aov_batches);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  VkDescriptorSet descriptor_set() const { return set_; }

 private:
  VulkanDevice& device_;
  std::vector<Buffer> buffers_;  // indexed by binding; BINDING_TLAS, _ACCUMULATION, _AOVS empty
  std::unique_ptr<SceneAccel> accel_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace tr
