#include "gpu_backend/rt_pipeline.h"

#include <cstring>
#include <vector>

#include "core/bindings.h"
#include "gpu_backend/gpu_error.h"
#include "shaders/batch.h"
#include "spirv/alpha.h"
#include "spirv/hit.h"
#include "spirv/miss.h"
#include "spirv/shape.h"

namespace tr {

namespace {

const uint32_t kMissCount = 1;
const uint32_t kHitGroupCount = 2;

VkDeviceSize align_up(VkDeviceSize x, VkDeviceSize a) { return (x + a - 1) / a * a; }

VkShaderModule make_module(VkDevice device, const uint32_t* code, size_t bytes) {
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = bytes;
  info.pCode = code;
  VkShaderModule module;
  vk_check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

VkRayTracingShaderGroupCreateInfoKHR group(VkRayTracingShaderGroupTypeKHR type, uint32_t general,
                                           uint32_t closest, uint32_t any, uint32_t intersection) {
  VkRayTracingShaderGroupCreateInfoKHR g{};
  g.sType = VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR;
  g.type = type;
  g.generalShader = general;
  g.closestHitShader = closest;
  g.anyHitShader = any;
  g.intersectionShader = intersection;
  return g;
}

}  // namespace

RayTracingPipeline::RayTracingPipeline(VulkanDevice& device, const std::vector<Spirv>& raygens,
                                       const SceneFeatures& features)
    : device_(device), raygens_(raygens.size()) {
  VkDevice d = device.handle();
  std::vector<VkShaderModule> modules;
  try {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t b = 0; b < BINDING_COUNT; ++b) {
      VkDescriptorSetLayoutBinding binding{};
      binding.binding = b;
      binding.descriptorCount = 1;
      binding.descriptorType = b == BINDING_TLAS ? VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR
                                                 : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      binding.stageFlags = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR |
                           VK_SHADER_STAGE_ANY_HIT_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR |
                           VK_SHADER_STAGE_MISS_BIT_KHR;
      bindings.push_back(binding);
    }
    VkDescriptorSetLayoutCreateInfo set_info{};
    set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    set_info.bindingCount = static_cast<uint32_t>(bindings.size());
    set_info.pBindings = bindings.data();
    vk_check(vkCreateDescriptorSetLayout(d, &set_info, nullptr, &set_layout_),
             "vkCreateDescriptorSetLayout");

    VkPushConstantRange push{};
    push.stageFlags = VK_SHADER_STAGE_RAYGEN_BIT_KHR;
    push.size = sizeof(BatchParams);
    VkPipelineLayoutCreateInfo layout_info{};
    layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    vk_check(vkCreatePipelineLayout(d, &layout_info, nullptr, &layout_), "vkCreatePipelineLayout");

    struct Stage {
      VkShaderStageFlagBits stage;
      Spirv spirv;
    };
    std::vector<Stage> stages;
    for (const Spirv& raygen : raygens) stages.push_back({VK_SHADER_STAGE_RAYGEN_BIT_KHR, raygen});
    const uint32_t R = static_cast<uint32_t>(raygens.size());
    stages.push_back({VK_SHADER_STAGE_MISS_BIT_KHR, {spirv_miss, sizeof(spirv_miss)}});
    stages.push_back({VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, {spirv_hit, sizeof(spirv_hit)}});
    stages.push_back({VK_SHADER_STAGE_INTERSECTION_BIT_KHR, {spirv_shape, sizeof(spirv_shape)}});
    // The any-hit stage only where the scene alpha-tests (lavapipe compiles a slower
    // traversal for a pipeline that has one).
    const bool alpha_tested = (features.material_flags & MATERIAL_ALPHA_TESTED) != 0;
    if (alpha_tested)
      stages.push_back({VK_SHADER_STAGE_ANY_HIT_BIT_KHR, {spirv_alpha, sizeof(spirv_alpha)}});
    // One uint per constant_id, in SceneFeatures order.
    const uint32_t kConstants = sizeof(SceneFeatures) / sizeof(uint32_t);
    VkSpecializationMapEntry entries[kConstants];
    for (uint32_t i = 0; i < kConstants; ++i)
      entries[i] = {i, i * uint32_t(sizeof(uint32_t)), sizeof(uint32_t)};
    VkSpecializationInfo specialization{kConstants, entries, sizeof(SceneFeatures), &features};
    std::vector<VkPipelineShaderStageCreateInfo> stage_infos;
    for (const Stage& s : stages) {
      modules.push_back(make_module(d, s.spirv.code, s.spirv.bytes));
      VkPipelineShaderStageCreateInfo info{};
      info.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
      info.stage = s.stage;
      info.module = modules.back();
      info.pName = "main";
      info.pSpecializationInfo = &specialization;
      stage_infos.push_back(info);
    }
    const uint32_t U = VK_SHADER_UNUSED_KHR;
    std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
    for (uint32_t i = 0; i < R; ++i)
      groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, i, U, U, U));
    groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, R, U, U, U));
    // Any-hit runs only on non-opaque (alpha-tested) triangle geometries.
    groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, U, R + 1,
                           alpha_tested ? R + 3 : U, U));
    groups.push_back(
        group(VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, U, R + 1, U, R + 2));
    VkRayTracingPipelineCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR;
    info.stageCount = static_cast<uint32_t>(stage_infos.size());
    info.pStages = stage_infos.data();
    info.groupCount = static_cast<uint32_t>(groups.size());
    info.pGroups = groups.data();
    info.maxPipelineRayRecursionDepth = 1;
    info.layout = layout_;
    vk_check(device.rt().create_ray_tracing_pipelines(d, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info,
                                                      nullptr, &pipeline_),
             "vkCreateRayTracingPipelinesKHR");
    for (VkShaderModule m : modules) vkDestroyShaderModule(d, m, nullptr);
    modules.clear();
    build_sbt();
  } catch (...) {
    for (VkShaderModule m : modules) vkDestroyShaderModule(d, m, nullptr);
    destroy();
    throw;
  }
}

// Shader binding table (Vulkan spec §40.1 "Shader Binding Table"): each region starts at a
// multiple of shaderGroupBaseAlignment, records are handles padded to
// shaderGroupHandleAlignment, and the raygen region's size equals its stride.
void RayTracingPipeline::build_sbt() {
  const auto& props = device_.rt_properties();
  const VkDeviceSize handle = props.shaderGroupHandleSize;
  const VkDeviceSize record = align_up(handle, props.shaderGroupHandleAlignment);
  const VkDeviceSize base = props.shaderGroupBaseAlignment;
  const uint32_t R = static_cast<uint32_t>(raygens_.size());
  const uint32_t group_count = R + kMissCount + kHitGroupCount;
  // Each ray-generation record is a region of its own, starting base-aligned.
  const VkDeviceSize raygen_size = align_up(record, base);
  for (VkStridedDeviceAddressRegionKHR& r : raygens_) r.stride = r.size = raygen_size;
  const VkDeviceSize raygen_bytes = R * raygen_size;
  miss_.stride = record;
  miss_.size = align_up(kMissCount * record, base);
  hit_.stride = record;
  hit_.size = align_up(kHitGroupCount * record, base);

  std::vector<uint8_t> handles(group_count * handle);
  vk_check(device_.rt().get_shader_group_handles(device_.handle(), pipeline_, 0, group_count,
                                                 handles.size(), handles.data()),
           "vkGetRayTracingShaderGroupHandlesKHR");
  const VkDeviceSize total = raygen_bytes + miss_.size + hit_.size;
  std::vector<uint8_t> table(total, 0);
  auto put = [&](uint32_t group_index, VkDeviceSize offset) {
    std::memcpy(table.data() + offset, handles.data() + group_index * handle, handle);
  };
  for (uint32_t i = 0; i < R; ++i) put(i, i * raygen_size);
  for (uint32_t i = 0; i < kMissCount; ++i) put(R + i, raygen_bytes + i * record);
  for (uint32_t i = 0; i < kHitGroupCount; ++i)
    put(R + kMissCount + i, raygen_bytes + miss_.size + i * record);

  // The table's own start must be base-aligned too: over-allocate and offset.
  std::vector<uint8_t> padded(total + base, 0);
  Buffer sbt(device_, total + base,
             VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR |
                 VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
             VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceSize shift = align_up(sbt.address(), base) - sbt.address();
  std::memcpy(padded.data() + shift, table.data(), total);
  Buffer staging(device_, padded.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  std::memcpy(staging.mapped(), padded.data(), padded.size());
  device_.submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, padded.size()};
    vkCmdCopyBuffer(cmd, staging.handle(), sbt.handle(), 1, &region);
  });
  sbt_ = std::move(sbt);
  VkDeviceAddress start = sbt_.address() + shift;
  for (uint32_t i = 0; i < R; ++i) raygens_[i].deviceAddress = start + i * raygen_size;
  miss_.deviceAddress = start + raygen_bytes;
  hit_.deviceAddress = start + raygen_bytes + miss_.size;
}

void RayTracingPipeline::trace(VkCommandBuffer cmd, uint32_t raygen, uint32_t width,
                               uint32_t height) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_);
  device_.rt().cmd_trace_rays(cmd, &raygens_.at(raygen), &miss_, &hit_, &callable_, width, height,
                              1);
}

VkDeviceSize RayTracingPipeline::raygen_stack_size(uint32_t raygen) const {
  return device_.rt().get_shader_group_stack_size(device_.handle(), pipeline_, raygen,
                                                  VK_SHADER_GROUP_SHADER_GENERAL_KHR);
}

RayTracingPipeline::~RayTracingPipeline() { destroy(); }

void RayTracingPipeline::destroy() {
  VkDevice d = device_.handle();
  if (pipeline_) vkDestroyPipeline(d, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(d, layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
}

}  // namespace tr
