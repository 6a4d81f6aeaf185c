// The Vulkan core functions twinray calls, as pointers that load_vulkan() takes from the Vulkan
// loader (libvulkan.so.1) opened when a process first uses Vulkan, not linked: a process that
// renders on the CPU does not map the loader (about 0.3 MiB resident) and runs where none is
// installed. The loader exports every core function (Vulkan loader interface, "Exported
// entry points"), so the pointers are the ones linking would have bound. Extension functions
// are fetched per device (gpu_backend/vk_device.cpp). Compiled with VK_NO_PROTOTYPES (set by
// the twinray_gpu target), so that a call of a function missing here does not compile.
#pragma once

#include <vulkan/vulkan.h>

// clang-format off
#define TWINRAY_VULKAN_FUNCTIONS(X) \
  X(vkAllocateCommandBuffers) \
  X(vkAllocateDescriptorSets) \
  X(vkAllocateMemory) \
  X(vkBeginCommandBuffer) \
  X(vkBindBufferMemory) \
  X(vkCmdBindDescriptorSets) \
  X(vkCmdBindPipeline) \
  X(vkCmdCopyBuffer) \
  X(vkCmdDispatch) \
  X(vkCmdPipelineBarrier) \
  X(vkCmdPushConstants) \
  X(vkCmdResetQueryPool) \
  X(vkCreateBuffer) \
  X(vkCreateCommandPool) \
  X(vkCreateComputePipelines) \
  X(vkCreateDescriptorPool) \
  X(vkCreateDescriptorSetLayout) \
  X(vkCreateDevice) \
  X(vkCreateFence) \
  X(vkCreateInstance) \
  X(vkCreatePipelineLayout) \
  X(vkCreateQueryPool) \
  X(vkCreateShaderModule) \
  X(vkDestroyBuffer) \
  X(vkDestroyCommandPool) \
  X(vkDestroyDescriptorPool) \
  X(vkDestroyDescriptorSetLayout) \
  X(vkDestroyDevice) \
  X(vkDestroyFence) \
  X(vkDestroyInstance) \
  X(vkDestroyPipeline) \
  X(vkDestroyPipelineLayout) \
  X(vkDestroyQueryPool) \
  X(vkDestroyShaderModule) \
  X(vkDeviceWaitIdle) \
  X(vkEndCommandBuffer) \
  X(vkEnumerateDeviceExtensionProperties) \
  X(vkEnumerateInstanceLayerProperties) \
  X(vkEnumeratePhysicalDevices) \
  X(vkFreeCommandBuffers) \
  X(vkFreeMemory) \
  X(vkGetBufferDeviceAddress) \
  X(vkGetBufferMemoryRequirements) \
  X(vkGetDeviceProcAddr) \
  X(vkGetDeviceQueue) \
  X(vkGetInstanceProcAddr) \
  X(vkGetPhysicalDeviceFeatures2) \
  X(vkGetPhysicalDeviceMemoryProperties) \
  X(vkGetPhysicalDeviceProperties) \
  X(vkGetPhysicalDeviceProperties2) \
  X(vkGetPhysicalDeviceQueueFamilyProperties) \
  X(vkGetQueryPoolResults) \
  X(vkMapMemory) \
  X(vkQueueSubmit) \
  X(vkResetCommandBuffer) \
  X(vkResetFences) \
  X(vkUpdateDescriptorSets) \
  X(vkWaitForFences)
// clang-format on

#define TWINRAY_DECLARE_VULKAN_FUNCTION(name) extern PFN_##name name;
TWINRAY_VULKAN_FUNCTIONS(TWINRAY_DECLARE_VULKAN_FUNCTION)
#undef TWINRAY_DECLARE_VULKAN_FUNCTION

namespace tr {

// Opens the loader and sets every pointer above, once (thread-safe). Throws BackendUnavailable
// (render/render.h) when the loader or one of the functions is missing.
void load_vulkan();

}  // namespace tr
