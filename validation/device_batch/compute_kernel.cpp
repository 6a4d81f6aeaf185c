#include "compute_kernel.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "gpu_backend/device_info.h"
#include "gpu_backend/gpu_error.h"

namespace tr::device_batch {
namespace {

// The largest query or result array of one submission: bounds the host-visible memory a batch
// holds, below the 128 MiB maxStorageBufferRange every Vulkan device offers (Vulkan 1.3 spec,
// table "Required Limits").
constexpr std::size_t kMaxArrayBytes = std::size_t(64) << 20;

struct PushConstants {
  uint32_t first;
  uint32_t count;
};

Buffer host_buffer(VulkanDevice& device, std::size_t bytes) {
  Buffer b(device, std::max<std::size_t>(bytes, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
           VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  std::memset(b.mapped(), 0, b.size());
  return b;
}

bool declared(const KernelLayout& layout, Binding at) {
  return at.set < layout.sets.size() &&
         std::find(layout.sets[at.set].begin(), layout.sets[at.set].end(), at.binding) !=
             layout.sets[at.set].end();
}

}  // namespace

ComputeKernel::ComputeKernel(const uint32_t* spirv, std::size_t spirv_bytes, KernelLayout layout,
                             const std::string& selector, std::string label)
    : layout_(std::move(layout)), label_(std::move(label)) {
  if (!declared(layout_, layout_.queries) || !declared(layout_, layout_.results))
    throw std::invalid_argument(label_ + ": the query and result arrays are not in the layout");
  instance_ = std::make_unique<VulkanInstance>();
  std::vector<DeviceInfo> devices = query_devices(instance_->handle());
  device_ = std::make_unique<VulkanDevice>(*instance_, select_device(devices, selector));
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(device_->physical(), &properties);
  limits_ = properties.limits;
  VkDevice d = device_->handle();

  uint32_t descriptors = 0;
  for (const std::vector<uint32_t>& bindings : layout_.sets) {
    std::vector<VkDescriptorSetLayoutBinding> entries;
    for (uint32_t b : bindings) {
      VkDescriptorSetLayoutBinding e{};
      e.binding = b;
      e.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      e.descriptorCount = 1;
      e.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
      entries.push_back(e);
    }
    descriptors += uint32_t(entries.size());
    VkDescriptorSetLayoutCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    info.bindingCount = uint32_t(entries.size());
    info.pBindings = entries.data();
    set_layouts_.push_back(VK_NULL_HANDLE);
    vk_check(vkCreateDescriptorSetLayout(d, &info, nullptr, &set_layouts_.back()),
             "vkCreateDescriptorSetLayout");
  }
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushConstants)};
  VkPipelineLayoutCreateInfo layout_info{};
  layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layout_info.setLayoutCount = uint32_t(set_layouts_.size());
  layout_info.pSetLayouts = set_layouts_.data();
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  vk_check(vkCreatePipelineLayout(d, &layout_info, nullptr, &pipeline_layout_),
           "vkCreatePipelineLayout");
  VkShaderModuleCreateInfo module{};
  module.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  module.codeSize = spirv_bytes;
  module.pCode = spirv;
  vk_check(vkCreateShaderModule(d, &module, nullptr, &module_), "vkCreateShaderModule");

  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, std::max(descriptors, 1u)};
  VkDescriptorPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pool_info.maxSets = uint32_t(set_layouts_.size());
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  vk_check(vkCreateDescriptorPool(d, &pool_info, nullptr, &pool_), "vkCreateDescriptorPool");
  sets_.resize(set_layouts_.size());
  VkDescriptorSetAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = uint32_t(set_layouts_.size());
  alloc.pSetLayouts = set_layouts_.data();
  vk_check(vkAllocateDescriptorSets(d, &alloc, sets_.data()), "vkAllocateDescriptorSets");
  empty_ = host_buffer(*device_, 0);
}

ComputeKernel::~ComputeKernel() {
  if (!device_) return;
  VkDevice d = device_->handle();
  vkDeviceWaitIdle(d);
  buffers_.clear();
  empty_ = Buffer();
  if (pool_) vkDestroyDescriptorPool(d, pool_, nullptr);
  if (pipeline_) vkDestroyPipeline(d, pipeline_, nullptr);
  if (module_) vkDestroyShaderModule(d, module_, nullptr);
  if (pipeline_layout_) vkDestroyPipelineLayout(d, pipeline_layout_, nullptr);
  for (VkDescriptorSetLayout l : set_layouts_) vkDestroyDescriptorSetLayout(d, l, nullptr);
  device_.reset();
}

double ComputeKernel::build(const std::vector<Specialization>& constants) {
  VkDevice d = device_->handle();
  if (pipeline_) vkDestroyPipeline(d, pipeline_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> values;
  for (const Specialization& c : constants) {
    entries.push_back({c.id, uint32_t(values.size() * sizeof(uint32_t)), sizeof(uint32_t)});
    values.push_back(c.value);
  }
  VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(),
                                      values.size() * sizeof(uint32_t), values.data()};
  VkComputePipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module_;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = constants.empty() ? nullptr : &specialization;
  info.layout = pipeline_layout_;
  auto start = std::chrono::steady_clock::now();
  vk_check(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
           ("vkCreateComputePipelines (" + label_ + ")").c_str());
  device_->check_validation();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void ComputeKernel::fill(Binding at, const void* data, std::size_t bytes) {
  if (!declared(layout_, at) ||
      (at.set == layout_.queries.set && at.binding == layout_.queries.binding) ||
      (at.set == layout_.results.set && at.binding == layout_.results.binding))
    throw std::invalid_argument(label_ + ": fill() of set " + std::to_string(at.set) + " binding " +
                                std::to_string(at.binding) +
                                ", which is no input buffer of the layout");
  auto it = buffers_.find(at);
  if (it == buffers_.end() || it->second.size() < bytes) {
    it = buffers_.insert_or_assign(at, host_buffer(*device_, bytes)).first;
    descriptors_stale_ = true;
  }
  char* mapped = static_cast<char*>(it->second.mapped());
  if (bytes > 0) std::memcpy(mapped, data, bytes);
  std::memset(mapped + bytes, 0, it->second.size() - bytes);
}

void ComputeKernel::write_descriptors() {
  std::vector<VkDescriptorBufferInfo> infos;
  std::vector<VkWriteDescriptorSet> writes;
  for (std::size_t s = 0; s < layout_.sets.size(); ++s) {
    for (uint32_t b : layout_.sets[s]) {
      auto it = buffers_.find(Binding{uint32_t(s), b});
      const Buffer& buffer = it == buffers_.end() ? empty_ : it->second;
      infos.push_back(VkDescriptorBufferInfo{buffer.handle(), 0, VK_WHOLE_SIZE});
    }
  }
  std::size_t i = 0;
  for (std::size_t s = 0; s < layout_.sets.size(); ++s) {
    for (uint32_t b : layout_.sets[s]) {
      VkWriteDescriptorSet w{};
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = sets_[s];
      w.dstBinding = b;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &infos[i++];
      writes.push_back(w);
    }
  }
  vkUpdateDescriptorSets(device_->handle(), uint32_t(writes.size()), writes.data(), 0, nullptr);
  descriptors_stale_ = false;
}

void ComputeKernel::evaluate(const void* queries, std::size_t query_size, void* results,
                             std::size_t result_size, std::size_t count) {
  if (pipeline_ == VK_NULL_HANDLE) throw GpuError(label_ + ": evaluate() before build()");
  if (query_size == 0 || result_size == 0)
    throw std::invalid_argument(label_ + ": evaluate() of empty queries or results");
  const std::size_t widest = std::max(query_size, result_size);
  const std::size_t max_batch =
      std::min<std::size_t>(kMaxArrayBytes, limits_.maxStorageBufferRange) / widest;
  const std::size_t batch = std::min(count, max_batch);
  for (auto [at, size] : {std::pair{layout_.queries, query_size}, {layout_.results, result_size}}) {
    auto it = buffers_.find(at);
    if (it == buffers_.end() || it->second.size() < batch * size) {
      buffers_.insert_or_assign(at, host_buffer(*device_, batch * size));
      descriptors_stale_ = true;
    }
  }
  if (descriptors_stale_) write_descriptors();
  const Buffer& query_buffer = buffers_.at(layout_.queries);
  const Buffer& result_buffer = buffers_.at(layout_.results);
  const uint64_t group = layout_.workgroup_size;
  const uint64_t max_groups = limits_.maxComputeWorkGroupCount[0];
  for (std::size_t first = 0; first < count; first += batch) {
    const uint32_t n = uint32_t(std::min(count - first, batch));
    std::memcpy(query_buffer.mapped(), static_cast<const char*>(queries) + first * query_size,
                n * query_size);
    device_->submit_and_wait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0,
                              uint32_t(sets_.size()), sets_.data(), 0, nullptr);
      for (uint64_t at = 0; at < n; at += group * max_groups) {
        PushConstants push{uint32_t(at), n};
        vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push),
                           &push);
        vkCmdDispatch(cmd, uint32_t(std::min(max_groups, (n - at + group - 1) / group)), 1, 1);
      }
      VkMemoryBarrier barrier{};
      barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
      barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                           1, &barrier, 0, nullptr, 0, nullptr);
    });
    std::memcpy(static_cast<char*>(results) + first * result_size, result_buffer.mapped(),
                n * result_size);
  }
  device_->check_validation();
}

}  // namespace tr::device_batch
