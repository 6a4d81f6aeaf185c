// Errors of the Vulkan backend: one-line messages, thrown, never a crash.
#pragma once

#include <stdexcept>
#include <string>

#include "gpu_backend/vulkan_api.h"

namespace tr {

class GpuError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

const char* vk_result_name(VkResult result);

// Throws GpuError("<what>: <VkResult name>") unless result is VK_SUCCESS.
void vk_check(VkResult result, const char* what);

}  // namespace tr
