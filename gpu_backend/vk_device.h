// The logical device of the ray-tracing backend: one compute-capable queue, a command pool,
// the ray-tracing entry points (loaded with vkGetDeviceProcAddr), and buffers with device
// addresses.
#pragma once

#include <functional>

#include "gpu_backend/device_info.h"
#include "gpu_backend/vk_instance.h"
#include "gpu_backend/vulkan_api.h"

namespace tr {

struct RayTracingFunctions {
  PFN_vkCreateAccelerationStructureKHR create_acceleration_structure;
  PFN_vkDestroyAccelerationStructureKHR destroy_acceleration_structure;
  PFN_vkGetAccelerationStructureBuildSizesKHR get_build_sizes;
  PFN_vkCmdBuildAccelerationStructuresKHR cmd_build_acceleration_structures;
  PFN_vkCmdWriteAccelerationStructuresPropertiesKHR cmd_write_acceleration_structure_properties;
  PFN_vkCmdCopyAccelerationStructureKHR cmd_copy_acceleration_structure;
  PFN_vkGetAccelerationStructureDeviceAddressKHR get_acceleration_structure_address;
  PFN_vkCreateRayTracingPipelinesKHR create_ray_tracing_pipelines;
  PFN_vkGetRayTracingShaderGroupHandlesKHR get_shader_group_handles;
  PFN_vkCmdTraceRaysKHR cmd_trace_rays;
  PFN_vkGetRayTracingShaderGroupStackSizeKHR get_shader_group_stack_size;
};

class VulkanDevice {
 public:
  VulkanDevice(VulkanInstance& instance, const DeviceInfo& info);
  ~VulkanDevice();
  VulkanDevice(const VulkanDevice&) = delete;
  VulkanDevice& operator=(const VulkanDevice&) = delete;

  VkDevice handle() const { return device_; }
  VkPhysicalDevice physical() const { return physical_; }
  const std::string& name() const { return name_; }
  const RayTracingFunctions& rt() const { return rt_; }
  const VkPhysicalDeviceRayTracingPipelinePropertiesKHR& rt_properties() const { return rt_props_; }
  const VkPhysicalDeviceAccelerationStructurePropertiesKHR& as_properties() const {
    return as_props_;
  }

  // Records commands with `record`, submits them, waits for completion, then fails on any
  // validation error reported meanwhile.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record);
  void check_validation() { instance_.check_validation(); }

  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                       VkMemoryPropertyFlags preferred) const;

 private:
  friend class AsyncCommands;
  void destroy();
  VulkanInstance& instance_;
  VkPhysicalDevice physical_;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::string name_;
  RayTracingFunctions rt_{};
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt_props_{};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR as_props_{};
  VkPhysicalDeviceMemoryProperties memory_{};
};

// A command buffer with its fence, for device work the host overlaps with its own.
class AsyncCommands {
 public:
  explicit AsyncCommands(VulkanDevice& device);
  ~AsyncCommands();
  AsyncCommands(const AsyncCommands&) = delete;
  AsyncCommands& operator=(const AsyncCommands&) = delete;

  // Waits for the previous submission, then records with `record` and submits.
  void submit(const std::function<void(VkCommandBuffer)>& record);
  // Waits for the pending submission, if any, then fails on any validation error.
  void wait();

 private:
  VulkanDevice& device_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool pending_ = false;
};

// A buffer with its own memory allocation; move-only.
class Buffer {
 public:
  Buffer() = default;
  Buffer(VulkanDevice& device, VkDeviceSize size, VkBufferUsageFlags usage,
         VkMemoryPropertyFlags memory);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  VkDeviceAddress address() const { return address_; }
  void* mapped() const { return mapped_; }  // host-visible buffers only

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  VkDeviceAddress address_ = 0;
  void* mapped_ = nullptr;
};

// A device-local buffer holding `size` bytes of `data` (usage gains TRANSFER_DST and
// SHADER_DEVICE_ADDRESS). An empty range yields a zeroed 16-byte buffer, so every binding
// has a valid buffer.
Buffer upload_buffer(VulkanDevice& device, const void* data, VkDeviceSize size,
                     VkBufferUsageFlags usage);

}  // namespace tr
