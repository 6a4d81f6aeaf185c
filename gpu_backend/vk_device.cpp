#include "gpu_backend/vk_device.h"

#include <cstring>
#include <utility>
#include <vector>

#include "gpu_backend/gpu_error.h"

namespace tr {

namespace {

template <typename Fn>
void load(VkDevice device, Fn& fn, const char* name) {
  fn = reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
  if (!fn) throw GpuError(std::string("Vulkan entry point ") + name + " not found");
}

}  // namespace

VulkanDevice::VulkanDevice(VulkanInstance& instance, const DeviceInfo& info)
    : instance_(instance), physical_(info.handle), name_(info.name) {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue_info.queueFamilyIndex = info.queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{};
  rt.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR;
  rt.rayTracingPipeline = VK_TRUE;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as{};
  as.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR;
  as.accelerationStructure = VK_TRUE;
  as.pNext = &rt;
  VkPhysicalDeviceVulkan12Features v12{};
  v12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
  v12.bufferDeviceAddress = VK_TRUE;
  v12.pNext = &as;

  VkDeviceCreateInfo device_info{};
  device_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  device_info.pNext = &v12;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  const std::vector<const char*>& extensions = required_device_extensions();
  device_info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  device_info.ppEnabledExtensionNames = extensions.data();
  vk_check(vkCreateDevice(physical_, &device_info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, info.queue_family, 0, &queue_);

  VkCommandPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = info.queue_family;
  try {
    vk_check(vkCreateCommandPool(device_, &pool_info, nullptr, &pool_), "vkCreateCommandPool");
    load(device_, rt_.create_acceleration_structure, "vkCreateAccelerationStructureKHR");
    load(device_, rt_.destroy_acceleration_structure, "vkDestroyAccelerationStructureKHR");
    load(device_, rt_.get_build_sizes, "vkGetAccelerationStructureBuildSizesKHR");
    load(device_, rt_.cmd_build_acceleration_structures, "vkCmdBuildAccelerationStructuresKHR");
    load(device_, rt_.cmd_write_acceleration_structure_properties,
         "vkCmdWriteAccelerationStructuresPropertiesKHR");
    load(device_, rt_.cmd_copy_acceleration_structure, "vkCmdCopyAccelerationStructureKHR");
    load(device_, rt_.get_acceleration_structure_address,
         "vkGetAccelerationStructureDeviceAddressKHR");
    load(device_, rt_.create_ray_tracing_pipelines, "vkCreateRayTracingPipelinesKHR");
    load(device_, rt_.get_shader_group_handles, "vkGetRayTracingShaderGroupHandlesKHR");
    load(device_, rt_.cmd_trace_rays, "vkCmdTraceRaysKHR");
    load(device_, rt_.get_shader_group_stack_size, "vkGetRayTracingShaderGroupStackSizeKHR");
  } catch (...) {
    destroy();
    throw;
  }

  as_props_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR;
  rt_props_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR;
  rt_props_.pNext = &as_props_;
  VkPhysicalDeviceProperties2 props{};
  props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
  props.pNext = &rt_props_;
  vkGetPhysicalDeviceProperties2(physical_, &props);
  rt_props_.pNext = nullptr;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
}

VulkanDevice::~VulkanDevice() { destroy(); }

void VulkanDevice::destroy() {
  if (device_ == VK_NULL_HANDLE) return;
  vkDeviceWaitIdle(device_);
  if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
  vkDestroyDevice(device_, nullptr);
  device_ = VK_NULL_HANDLE;
}

void VulkanDevice::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  AsyncCommands commands(*this);
  commands.submit(record);
  commands.wait();
}

AsyncCommands::AsyncCommands(VulkanDevice& device) : device_(device) {
  VkCommandBufferAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  alloc.commandPool = device.pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  vk_check(vkAllocateCommandBuffers(device.device_, &alloc, &cmd_), "vkAllocateCommandBuffers");
  VkFenceCreateInfo fence_info{};
  fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkResult r = vkCreateFence(device.device_, &fence_info, nullptr, &fence_);
  if (r != VK_SUCCESS) {
    vkFreeCommandBuffers(device.device_, device.pool_, 1, &cmd_);
    vk_check(r, "vkCreateFence");
  }
}

AsyncCommands::~AsyncCommands() {
  if (pending_) vkWaitForFences(device_.device_, 1, &fence_, VK_TRUE, UINT64_MAX);
  vkDestroyFence(device_.device_, fence_, nullptr);
  vkFreeCommandBuffers(device_.device_, device_.pool_, 1, &cmd_);
}

void AsyncCommands::submit(const std::function<void(VkCommandBuffer)>& record) {
  wait();
  vk_check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk_check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
  record(cmd_);
  vk_check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
  device_.check_validation();
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_;
  vk_check(vkResetFences(device_.device_, 1, &fence_), "vkResetFences");
  vk_check(vkQueueSubmit(device_.queue_, 1, &submit, fence_), "vkQueueSubmit");
  pending_ = true;
}

void AsyncCommands::wait() {
  if (pending_) {
    pending_ = false;
    vk_check(vkWaitForFences(device_.device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  }
  device_.check_validation();
}

uint32_t VulkanDevice::memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
  for (VkMemoryPropertyFlags wanted : {required | preferred, required})
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
      if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & wanted) == wanted)
        return i;
  throw GpuError("no Vulkan memory type with the required properties");
}

Buffer::Buffer(VulkanDevice& device, VkDeviceSize size, VkBufferUsageFlags usage,
               VkMemoryPropertyFlags memory)
    : device_(device.handle()), size_(size) {
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vk_check(vkCreateBuffer(device_, &info, nullptr, &buffer_), "vkCreateBuffer");

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, buffer_, &req);
  VkMemoryAllocateFlagsInfo flags{};
  flags.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO;
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  alloc.pNext = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) ? &flags : nullptr;
  alloc.allocationSize = req.size;
  VkMemoryPropertyFlags preferred =
      (memory & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : 0;
  try {
    alloc.memoryTypeIndex = device.memory_type(req.memoryTypeBits, memory, preferred);
    vk_check(vkAllocateMemory(device_, &alloc, nullptr, &memory_), "vkAllocateMemory");
    vk_check(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory");
    if (memory & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
      vk_check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
  } catch (...) {
    release();
    throw;
  }
  if (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) {
    VkBufferDeviceAddressInfo address{};
    address.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO;
    address.buffer = buffer_;
    address_ = vkGetBufferDeviceAddress(device_, &address);
  }
}

Buffer::~Buffer() { release(); }

void Buffer::release() {
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    device_ = other.device_;
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = other.size_;
    address_ = other.address_;
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

Buffer upload_buffer(VulkanDevice& device, const void* data, VkDeviceSize size,
                     VkBufferUsageFlags usage) {
  const VkDeviceSize kDummySize = 16;
  VkDeviceSize stored = size == 0 ? kDummySize : size;
  Buffer staging(device, stored, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  if (size == 0)
    std::memset(staging.mapped(), 0, kDummySize);
  else
    std::memcpy(staging.mapped(), data, size);
  Buffer buffer(
      device, stored,
      usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  device.submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, stored};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer.handle(), 1, &region);
  });
  return buffer;
}

}  // namespace tr
