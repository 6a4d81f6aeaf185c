// The Vulkan instance, with the Khronos validation layer and a debug messenger when the
// environment sets TWINRAY_VK_VALIDATION=1. Validation errors are collected and turned into a
// GpuError at the next check point, so a render that provokes one fails loudly.
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include "gpu_backend/vulkan_api.h"

namespace tr {

class VulkanInstance {
 public:
  VulkanInstance();
  ~VulkanInstance();
  VulkanInstance(const VulkanInstance&) = delete;
  VulkanInstance& operator=(const VulkanInstance&) = delete;

  VkInstance handle() const { return instance_; }
  bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }

  // Throws GpuError carrying the first validation error reported so far, if any.
  void check_validation();
  // Called by the messenger.
  void report_error(const std::string& message);

 private:
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  std::mutex mutex_;
  std::vector<std::string> errors_;
};

// TWINRAY_VK_VALIDATION=1 in the environment.
bool validation_requested();

}  // namespace tr
