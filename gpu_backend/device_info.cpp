#include "gpu_backend/device_info.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "gpu_backend/gpu_error.h"
#include "render/render.h"

namespace tr {

const std::vector<const char*>& required_device_extensions() {
  static const std::vector<const char*> extensions = {
      VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
      VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
      VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
  };
  return extensions;
}

namespace {

std::string type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU";
    default:
      return "other";
  }
}

std::string version_string(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
         "." + std::to_string(VK_API_VERSION_PATCH(v));
}

DeviceInfo inspect(uint32_t index, VkPhysicalDevice device) {
  DeviceInfo info;
  info.index = index;
  info.handle = device;
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(device, &props);
  info.name = props.deviceName;
  info.type = type_name(props.deviceType);
  info.cpu = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  info.api_version = version_string(props.apiVersion);
  if (props.apiVersion < VK_API_VERSION_1_3)
    info.missing.push_back("Vulkan 1.3 (device offers " + info.api_version + ")");

  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> available(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, available.data());
  bool has_extensions = true;
  for (const char* needed : required_device_extensions()) {
    bool found = std::any_of(
        available.begin(), available.end(),
        [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, needed) == 0; });
    if (!found) {
      info.missing.push_back(std::string("extension ") + needed);
      has_extensions = false;
    }
  }

  if (props.apiVersion >= VK_API_VERSION_1_2 && has_extensions) {
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{};
    rt.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR;
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as{};
    as.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR;
    as.pNext = &rt;
    VkPhysicalDeviceVulkan12Features v12{};
    v12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    v12.pNext = &as;
    VkPhysicalDeviceFeatures2 features{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.pNext = &v12;
    vkGetPhysicalDeviceFeatures2(device, &features);
    if (!v12.bufferDeviceAddress) info.missing.push_back("feature bufferDeviceAddress");
    if (!as.accelerationStructure) info.missing.push_back("feature accelerationStructure");
    if (!rt.rayTracingPipeline) info.missing.push_back("feature rayTracingPipeline");
  }

  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  auto compute = std::find_if(
      families.begin(), families.end(),
      [](const VkQueueFamilyProperties& f) { return (f.queueFlags & VK_QUEUE_COMPUTE_BIT) != 0; });
  if (compute == families.end())
    info.missing.push_back("a compute queue");
  else
    info.queue_family = static_cast<uint32_t>(compute - families.begin());
  return info;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string device_list(const std::vector<DeviceInfo>& devices) {
  std::string out;
  for (const DeviceInfo& d : devices)
    out += (out.empty() ? "" : "; ") + std::to_string(d.index) + ": " + d.name;
  return out.empty() ? "none" : out;
}

}  // namespace

std::vector<DeviceInfo> query_devices(VkInstance instance) {
  uint32_t count = 0;
  vk_check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> handles(count);
  vk_check(vkEnumeratePhysicalDevices(instance, &count, handles.data()),
           "vkEnumeratePhysicalDevices");
  std::vector<DeviceInfo> devices;
  for (uint32_t i = 0; i < count; ++i) devices.push_back(inspect(i, handles[i]));
  return devices;
}

std::string describe(const DeviceInfo& d) {
  std::string line =
      std::to_string(d.index) + ": " + d.name + " (" + d.type + ", Vulkan " + d.api_version + ") ";
  return line + (d.usable() ? "usable" : "not usable: missing " + join(d.missing));
}

const DeviceInfo& select_device(const std::vector<DeviceInfo>& devices,
                                const std::string& selector) {
  const std::string hint = "; use --backend cpu";
  if (devices.empty()) throw BackendUnavailable("no Vulkan device found" + hint);
  if (selector.empty()) {
    for (const DeviceInfo& d : devices)
      if (d.usable()) return d;
    std::string why;
    for (const DeviceInfo& d : devices) why += (why.empty() ? "" : "; ") + describe(d);
    throw BackendUnavailable("no Vulkan device supports ray tracing (" + why + ")" + hint);
  }
  const DeviceInfo* chosen = nullptr;
  bool numeric = std::all_of(selector.begin(), selector.end(),
                             [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  if (numeric) {
    unsigned long index = std::stoul(selector);
    if (index >= devices.size())
      throw BackendUnavailable("no Vulkan device with index " + selector +
                               " (devices: " + device_list(devices) + ")" + hint);
    chosen = &devices[index];
  } else {
    for (const DeviceInfo& d : devices)
      if (lower(d.name).find(lower(selector)) != std::string::npos) {
        if (d.usable()) return d;
        if (!chosen) chosen = &d;
      }
    if (!chosen)
      throw BackendUnavailable("no Vulkan device matches '" + selector +
                               "' (devices: " + device_list(devices) + ")" + hint);
  }
  if (!chosen->usable()) throw BackendUnavailable("Vulkan device " + describe(*chosen) + hint);
  return *chosen;
}

}  // namespace tr
