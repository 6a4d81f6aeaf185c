#include "gpu_backend/gpu_scene.h"

#include "core/bindings.h"
#include "core/samplers/sobol_matrices.h"
#include "gpu_backend/gpu_error.h"

namespace tr {

namespace {

template <typename T>
Buffer upload_vector(VulkanDevice& device, const std::vector<T>& v, VkBufferUsageFlags usage) {
  return upload_buffer(device, v.data(), v.size() * sizeof(T), usage);
}

}  // namespace

GpuScene::GpuScene(VulkanDevice& device, const SceneBuffers& scene, VkDescriptorSetLayout layout,
                   const Buffer& batches, const Buffer& aov_batches)
    : device_(device) {
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  const VkBufferUsageFlags build_input =
      storage | VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;
  buffers_.resize(BINDING_COUNT);
  buffers_[BINDING_GLOBALS] = upload_buffer(device, &scene.globals, sizeof(SceneGlobals), storage);
  buffers_[BINDING_MATERIALS] = upload_vector(device, scene.materials, storage);
  buffers_[BINDING_TEXTURES] = upload_vector(device, scene.textures, storage);
  buffers_[BINDING_TEXELS] = upload_vector(device, scene.texels, storage);
  buffers_[BINDING_EMITTERS] = upload_vector(device, scene.emitters, storage);
  buffers_[BINDING_ALIAS] = upload_vector(device, scene.alias, storage);
  buffers_[BINDING_LIGHT_NODES] = upload_vector(device, scene.light_nodes, storage);
  buffers_[BINDING_SHAPES] = upload_vector(device, scene.shapes, storage);
  buffers_[BINDING_INSTANCES] = upload_vector(device, scene.instances, storage);
  buffers_[BINDING_POSITIONS] = upload_vector(device, scene.positions, build_input);
  buffers_[BINDING_NORMALS] = upload_vector(device, scene.normals, storage);
  buffers_[BINDING_UVS] = upload_vector(device, scene.uvs, storage);
  buffers_[BINDING_INDICES] = upload_vector(device, scene.indices, build_input);
  buffers_[BINDING_ATTRIBUTES] = upload_vector(device, scene.attributes, storage);
  buffers_[BINDING_SOBOL] =
      upload_buffer(device, SOBOL_NIBBLE_TABLE.xy, sizeof(SOBOL_NIBBLE_TABLE.xy), storage);
  GeometryLayout geometry = geometry_layout(scene);
  buffers_[BINDING_GEOMETRY_SHAPES] = upload_vector(device, geometry.table, storage);
  accel_ = std::make_unique<SceneAccel>(device, scene, geometry, buffers_[BINDING_POSITIONS],
                                        buffers_[BINDING_INDICES]);

  VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, BINDING_COUNT - 1}};
  VkDescriptorPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 2;
  pool_info.pPoolSizes = sizes;
  vk_check(vkCreateDescriptorPool(device.handle(), &pool_info, nullptr, &pool_),
           "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  VkResult r = vkAllocateDescriptorSets(device.handle(), &alloc, &set_);
  if (r != VK_SUCCESS) {
    vkDestroyDescriptorPool(device.handle(), pool_, nullptr);
    vk_check(r, "vkAllocateDescriptorSets");
  }

  VkAccelerationStructureKHR tlas = accel_->tlas();
  VkWriteDescriptorSetAccelerationStructureKHR as_write{};
  as_write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR;
  as_write.accelerationStructureCount = 1;
  as_write.pAccelerationStructures = &tlas;
  std::vector<VkDescriptorBufferInfo> infos(BINDING_COUNT);
  std::vector<VkWriteDescriptorSet> writes;
  for (uint32_t b = 0; b < BINDING_COUNT; ++b) {
    VkWriteDescriptorSet w{};
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.dstSet = set_;
    w.dstBinding = b;
    w.descriptorCount = 1;
    if (b == BINDING_TLAS) {
      w.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
      w.pNext = &as_write;
    } else {
      const Buffer& buffer = b == BINDING_ACCUMULATION ? batches
                             : b == BINDING_AOVS       ? aov_batches
                                                       : buffers_[b];
      infos[b] = VkDescriptorBufferInfo{buffer.handle(), 0, VK_WHOLE_SIZE};
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &infos[b];
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device.handle(), static_cast<uint32_t>(writes.size()), writes.data(), 0,
                         nullptr);
}

GpuScene::~GpuScene() {
  if (pool_) vkDestroyDescriptorPool(device_.handle(), pool_, nullptr);
}

}  // namespace tr
