#include "probe_device.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "core/bindings.h"
#include "gpu_backend/device_info.h"
#include "gpu_backend/gpu_error.h"
#include "spirv/bsdf_probe.h"

namespace tr::bsdf_gpu {
namespace {

constexpr uint32_t kWorkgroup = 64;     // local_size_x of bsdf_probe.comp
constexpr uint32_t kMaxGroups = 65535;  // per dispatch (maxComputeWorkGroupCount minimum)
// Queries per batch: 64 MiB of queries, within the 128 MiB maxStorageBufferRange minimum.
constexpr std::size_t kMaxBatch = std::size_t(1) << 20;
constexpr uint32_t kSceneBindings[] = {
    BINDING_GLOBALS, BINDING_MATERIALS, BINDING_TEXTURES,  BINDING_TEXELS,    BINDING_EMITTERS,
    BINDING_ALIAS,   BINDING_SHAPES,    BINDING_INSTANCES, BINDING_POSITIONS, BINDING_NORMALS,
    BINDING_UVS,     BINDING_INDICES,   BINDING_ATTRIBUTES};

struct PushConstants {
  uint32_t first;
  uint32_t count;
};

VkDescriptorSetLayout storage_layout(VkDevice device, const std::vector<uint32_t>& bindings) {
  std::vector<VkDescriptorSetLayoutBinding> entries;
  for (uint32_t b : bindings) {
    VkDescriptorSetLayoutBinding e{};
    e.binding = b;
    e.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    e.descriptorCount = 1;
    e.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    entries.push_back(e);
  }
  VkDescriptorSetLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  info.bindingCount = static_cast<uint32_t>(entries.size());
  info.pBindings = entries.data();
  VkDescriptorSetLayout layout;
  vk_check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout),
           "vkCreateDescriptorSetLayout");
  return layout;
}

Buffer host_buffer(VulkanDevice& device, const void* data, size_t bytes) {
  const size_t stored = bytes == 0 ? 16 : bytes;
  Buffer b(device, stored, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
           VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  if (bytes == 0)
    std::memset(b.mapped(), 0, stored);
  else if (data != nullptr)
    std::memcpy(b.mapped(), data, bytes);
  return b;
}

template <typename T>
Buffer host_vector(VulkanDevice& device, const std::vector<T>& v) {
  return host_buffer(device, v.data(), v.size() * sizeof(T));
}

// A descriptor pool with the two sets of one evaluation, freed with it.
struct Sets {
  VkDevice device;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet scene = VK_NULL_HANDLE, io = VK_NULL_HANDLE;
  Sets(VkDevice d, VkDescriptorSetLayout scene_layout, VkDescriptorSetLayout io_layout)
      : device(d) {
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 16};
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = 2;
    info.poolSizeCount = 1;
    info.pPoolSizes = &size;
    vk_check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
    VkDescriptorSetLayout layouts[2] = {scene_layout, io_layout};
    VkDescriptorSet sets[2];
    VkDescriptorSetAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    alloc.descriptorPool = pool;
    alloc.descriptorSetCount = 2;
    alloc.pSetLayouts = layouts;
    VkResult r = vkAllocateDescriptorSets(device, &alloc, sets);
    if (r != VK_SUCCESS) {
      vkDestroyDescriptorPool(device, pool, nullptr);
      vk_check(r, "vkAllocateDescriptorSets");
    }
    scene = sets[0];
    io = sets[1];
  }
  ~Sets() { vkDestroyDescriptorPool(device, pool, nullptr); }
  Sets(const Sets&) = delete;
  Sets& operator=(const Sets&) = delete;
};

}  // namespace

ProbeDevice::ProbeDevice() {
  instance_ = std::make_unique<VulkanInstance>();
  std::vector<DeviceInfo> devices = query_devices(instance_->handle());
  device_ = std::make_unique<VulkanDevice>(*instance_, select_device(devices, ""));
  VkDevice d = device_->handle();
  scene_layout_ = storage_layout(
      d, std::vector<uint32_t>(std::begin(kSceneBindings), std::end(kSceneBindings)));
  io_layout_ = storage_layout(d, {0, 1});
  VkDescriptorSetLayout sets[2] = {scene_layout_, io_layout_};
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushConstants)};
  VkPipelineLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  info.setLayoutCount = 2;
  info.pSetLayouts = sets;
  info.pushConstantRangeCount = 1;
  info.pPushConstantRanges = &push;
  vk_check(vkCreatePipelineLayout(d, &info, nullptr, &layout_), "vkCreatePipelineLayout");
  VkShaderModuleCreateInfo module{};
  module.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  module.codeSize = sizeof(spirv_bsdf_probe);
  module.pCode = spirv_bsdf_probe;
  vk_check(vkCreateShaderModule(d, &module, nullptr, &module_), "vkCreateShaderModule");
  empty_ = host_buffer(*device_, nullptr, 0);
}

ProbeDevice::~ProbeDevice() {
  if (!device_) return;
  VkDevice d = device_->handle();
  vkDeviceWaitIdle(d);
  destroy_pipeline();
  vkDestroyShaderModule(d, module_, nullptr);
  vkDestroyPipelineLayout(d, layout_, nullptr);
  vkDestroyDescriptorSetLayout(d, io_layout_, nullptr);
  vkDestroyDescriptorSetLayout(d, scene_layout_, nullptr);
  empty_ = Buffer();
  query_buffer_ = Buffer();
  result_buffer_ = Buffer();
  device_.reset();
}

void ProbeDevice::destroy_pipeline() {
  if (pipeline_) vkDestroyPipeline(device_->handle(), pipeline_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
}

double ProbeDevice::build(const ProbeVariant& variant) {
  destroy_pipeline();
  // constant_id 0..5: shaders/features.glsl (BSDFs, emitters, shapes, textures, material
  // flags, integrators); 100: the broken variant (bsdf_probe.comp).
  const uint32_t constants[7] = {variant.bsdf_types,
                                 0u,
                                 0u,
                                 variant.texture_types,
                                 variant.material_flags,
                                 0u,
                                 variant.pdf_off_by_cosine ? 1u : 0u};
  VkSpecializationMapEntry entries[7];
  for (uint32_t i = 0; i < 7; ++i) entries[i] = {i == 6 ? 100u : i, i * 4u, 4u};
  VkSpecializationInfo specialization{7, entries, sizeof(constants), constants};
  VkComputePipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module_;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = &specialization;
  info.layout = layout_;
  auto start = std::chrono::steady_clock::now();
  vk_check(
      vkCreateComputePipelines(device_->handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
      "vkCreateComputePipelines (bsdf_probe.comp)");
  device_->check_validation();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void ProbeDevice::evaluate(const std::vector<ProbeQuery>& queries, const ProbeScene& scene,
                           ProbeResult* results) {
  if (pipeline_ == VK_NULL_HANDLE) throw GpuError("bsdf probe: evaluate() before build()");
  const std::size_t capacity = std::min(queries.size(), kMaxBatch);
  if (capacity > io_capacity_) {
    query_buffer_ = host_buffer(*device_, nullptr, capacity * sizeof(ProbeQuery));
    result_buffer_ = host_buffer(*device_, nullptr, capacity * sizeof(ProbeResult));
    io_capacity_ = capacity;
  }
  Buffer materials = host_vector(*device_, *scene.materials);
  Buffer textures = host_vector(*device_, *scene.textures);
  Buffer texels = host_vector(*device_, *scene.texels);
  for (std::size_t first = 0; first < queries.size(); first += kMaxBatch) {
    const std::size_t count = std::min(queries.size() - first, kMaxBatch);
    std::memcpy(query_buffer_.mapped(), queries.data() + first, count * sizeof(ProbeQuery));
    dispatch(uint32_t(count), materials, textures, texels);
    std::memcpy(results + first, result_buffer_.mapped(), count * sizeof(ProbeResult));
  }
}

void ProbeDevice::dispatch(uint32_t count, const Buffer& materials, const Buffer& textures,
                           const Buffer& texels) {
  VulkanDevice& device = *device_;
  Sets sets(device.handle(), scene_layout_, io_layout_);
  std::vector<VkDescriptorBufferInfo> infos;
  infos.reserve(16);
  std::vector<VkWriteDescriptorSet> writes;
  auto bind = [&](VkDescriptorSet set, uint32_t binding, const Buffer& b) {
    infos.push_back(VkDescriptorBufferInfo{b.handle(), 0, VK_WHOLE_SIZE});
    VkWriteDescriptorSet w{};
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w.pBufferInfo = &infos.back();
    writes.push_back(w);
  };
  for (uint32_t b : kSceneBindings) {
    bind(sets.scene, b,
         b == BINDING_MATERIALS  ? materials
         : b == BINDING_TEXTURES ? textures
         : b == BINDING_TEXELS   ? texels
                                 : empty_);
  }
  bind(sets.io, 0, query_buffer_);
  bind(sets.io, 1, result_buffer_);
  vkUpdateDescriptorSets(device.handle(), static_cast<uint32_t>(writes.size()), writes.data(), 0,
                         nullptr);

  device.submit_and_wait([&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    VkDescriptorSet bound[2] = {sets.scene, sets.io};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 2, bound, 0, nullptr);
    for (uint32_t first = 0; first < count; first += kWorkgroup * kMaxGroups) {
      PushConstants push{first, count};
      vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
      uint32_t groups = std::min(kMaxGroups, (count - first + kWorkgroup - 1) / kWorkgroup);
      vkCmdDispatch(cmd, groups, 1, 1);
    }
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &barrier, 0, nullptr, 0, nullptr);
  });
}

}  // namespace tr::bsdf_gpu
