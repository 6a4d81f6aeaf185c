// Physical devices and what the ray-tracing backend needs from them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu_backend/vulkan_api.h"

namespace tr {

struct DeviceInfo {
  uint32_t index = 0;
  VkPhysicalDevice handle = VK_NULL_HANDLE;
  std::string name;
  std::string type;  // "discrete GPU", "CPU", ...
  bool cpu = false;  // a software rasteriser on the host (lavapipe)
  std::string api_version;
  std::vector<std::string> missing;  // what the backend needs and the device lacks
  uint32_t queue_family = 0;         // a queue family with compute, when usable
  bool usable() const { return missing.empty(); }
};

// The device extensions the backend enables.
const std::vector<const char*>& required_device_extensions();

std::vector<DeviceInfo> query_devices(VkInstance instance);

// Picks a device: "" the first usable one, a decimal index, or a case-insensitive name
// substring. Throws BackendUnavailable naming what is missing (and suggesting --backend cpu) when
// the choice is not usable or none matches.
const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices,
                                const std::string& selector);

// One line per device: index, name, type, and "usable" or what is missing.
std::string describe(const DeviceInfo& device);

}  // namespace tr
