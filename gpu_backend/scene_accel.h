// Acceleration structures of a scene. Every Instance record gets up to two BLASes (Vulkan
// cannot mix geometry types in one): one with a triangle geometry per mesh shape, one with
// an AABB geometry per analytic shape (intersected by shaders/shape.rint). The TLAS places
// each BLAS with its Instance.to_world; instanceCustomIndex is the Instance index and the
// SBT offset selects the triangle (0) or procedural (1) hit group.
//
// Every structure is built with ALLOW_COMPACTION, its compacted size read back through a
// VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR query, and copied with
// VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR into a structure of that size; the
// full-size originals are freed (Vulkan spec, VK_KHR_acceleration_structure: "Acceleration
// Structure Queries" and vkCmdCopyAccelerationStructureKHR). The BLASes are compacted before
// the TLAS is built, so the TLAS references only compacted BLASes.
//
// Geometry -> shape table (binding BINDING_GEOMETRY_SHAPES): entry i < TLAS instance count
// is the table offset of TLAS instance i; the global shape index of geometry g of TLAS
// instance i is table[table[i] + g].
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gpu_backend/vk_device.h"
#include "scenes/scene.h"

namespace tr {

const uint32_t HIT_GROUP_TRIANGLES = 0;
const uint32_t HIT_GROUP_PROCEDURAL = 1;

// The table described above, and for each TLAS instance its Instance index and kind.
struct GeometryLayout {
  struct Entry {
    uint32_t instance;
    bool procedural;
    std::vector<uint32_t> shapes;
  };
  std::vector<Entry> blases;
  std::vector<uint32_t> table;
};

GeometryLayout geometry_layout(const SceneBuffers& scene);

// Object-space bounds of an analytic shape, carried to its instance's space by to_world and
// padded, as a VkAabbPositionsKHR.
VkAabbPositionsKHR shape_bounds(const Shape& shape);

class AccelerationStructure {
 public:
  AccelerationStructure(VulkanDevice& device, VkAccelerationStructureTypeKHR type,
                        VkDeviceSize size);
  ~AccelerationStructure();
  AccelerationStructure(const AccelerationStructure&) = delete;
  AccelerationStructure& operator=(const AccelerationStructure&) = delete;

  VkAccelerationStructureKHR handle() const { return handle_; }
  VkDeviceAddress address() const { return address_; }
  VkDeviceSize size() const { return size_; }

 private:
  VulkanDevice& device_;
  VkDeviceSize size_;
  Buffer storage_;
  VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
  VkDeviceAddress address_ = 0;
};

// Bytes of the acceleration structures (VkAccelerationStructureCreateInfoKHR::size): as built
// (vkGetAccelerationStructureBuildSizesKHR) and as kept after compaction.
struct AccelMemory {
  VkDeviceSize blas_built = 0;
  VkDeviceSize blas_compacted = 0;
  VkDeviceSize tlas_built = 0;
  VkDeviceSize tlas_compacted = 0;
};

class SceneAccel {
 public:
  // positions/indices: the uploaded scene buffers (with AS build-input usage).
  SceneAccel(VulkanDevice& device, const SceneBuffers& scene, const GeometryLayout& layout,
             const Buffer& positions, const Buffer& indices);
  SceneAccel(const SceneAccel&) = delete;
  SceneAccel& operator=(const SceneAccel&) = delete;

  VkAccelerationStructureKHR tlas() const { return tlas_->handle(); }
  const AccelMemory& memory() const { return memory_; }

 private:
  AccelMemory memory_;
  std::vector<std::unique_ptr<AccelerationStructure>> blases_;
  std::unique_ptr<AccelerationStructure> tlas_;
};

}  // namespace tr
