#include "gpu_backend/scene_accel.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/shapes/bounds.h"
#include "gpu_backend/gpu_error.h"

namespace tr {

namespace {

const VkBufferUsageFlags kBuildInput =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

VkDeviceSize align_up(VkDeviceSize x, VkDeviceSize a) { return (x + a - 1) / a * a; }

}  // namespace

GeometryLayout geometry_layout(const SceneBuffers& scene) {
  GeometryLayout layout;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& inst = scene.instances[i];
    GeometryLayout::Entry meshes{i, false, {}};
    GeometryLayout::Entry analytic{i, true, {}};
    for (uint32_t s = inst.first_shape; s < inst.first_shape + inst.shape_count; ++s) {
      const Shape& shape = scene.shapes.at(s);
      if (shape.type == SHAPE_MESH) {
        if (shape.triangle_count > 0) meshes.shapes.push_back(s);
      } else {
        analytic.shapes.push_back(s);
      }
    }
    if (!meshes.shapes.empty()) layout.blases.push_back(meshes);
    if (!analytic.shapes.empty()) layout.blases.push_back(analytic);
  }
  layout.table.resize(layout.blases.size());
  for (size_t b = 0; b < layout.blases.size(); ++b) {
    layout.table[b] = static_cast<uint32_t>(layout.table.size());
    layout.table.insert(layout.table.end(), layout.blases[b].shapes.begin(),
                        layout.blases[b].shapes.end());
  }
  return layout;
}

VkAabbPositionsKHR shape_bounds(const Shape& shape) {
  vec3 wlo, whi;
  analytic_shape_bounds(shape, wlo, whi);
  // Conservative padding: the box only culls, the intersection shader decides.
  vec3 pad = 1e-3f * (whi - wlo) + vec3(1e-4f * std::max(1.0f, max_component(abs(whi) + abs(wlo))));
  wlo -= pad;
  whi += pad;
  return VkAabbPositionsKHR{wlo.x, wlo.y, wlo.z, whi.x, whi.y, whi.z};
}

AccelerationStructure::AccelerationStructure(VulkanDevice& device,
                                             VkAccelerationStructureTypeKHR type, VkDeviceSize size)
    : device_(device),
      size_(size),
      storage_(device, size,
               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
               VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) {
  VkAccelerationStructureCreateInfoKHR info{};
  info.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR;
  info.buffer = storage_.handle();
  info.size = size;
  info.type = type;
  vk_check(device.rt().create_acceleration_structure(device.handle(), &info, nullptr, &handle_),
           "vkCreateAccelerationStructureKHR");
  VkAccelerationStructureDeviceAddressInfoKHR address{};
  address.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR;
  address.accelerationStructure = handle_;
  address_ = device.rt().get_acceleration_structure_address(device.handle(), &address);
}

AccelerationStructure::~AccelerationStructure() {
  device_.rt().destroy_acceleration_structure(device_.handle(), handle_, nullptr);
}

namespace {

// One pending build: geometries, ranges, and the structure and scratch it writes.
struct Build {
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
  VkAccelerationStructureBuildGeometryInfoKHR info{};
  VkDeviceSize scratch_offset = 0;
};

std::unique_ptr<AccelerationStructure> prepare(VulkanDevice& device, Build& build,
                                               VkAccelerationStructureTypeKHR type,
                                               VkDeviceSize& scratch_total) {
  build.info.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR;
  build.info.type = type;
  build.info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                     VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
  build.info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.info.geometryCount = static_cast<uint32_t>(build.geometries.size());
  build.info.pGeometries = build.geometries.data();
  std::vector<uint32_t> counts;
  for (const auto& r : build.ranges) counts.push_back(r.primitiveCount);
  VkAccelerationStructureBuildSizesInfoKHR sizes{};
  sizes.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR;
  device.rt().get_build_sizes(device.handle(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                              &build.info, counts.data(), &sizes);
  auto as = std::make_unique<AccelerationStructure>(device, type, sizes.accelerationStructureSize);
  build.info.dstAccelerationStructure = as->handle();
  VkDeviceSize alignment = std::max<VkDeviceSize>(
      device.as_properties().minAccelerationStructureScratchOffsetAlignment, 1);
  build.scratch_offset = align_up(scratch_total, alignment);
  scratch_total = build.scratch_offset + std::max<VkDeviceSize>(sizes.buildScratchSize, 1);
  return as;
}

void record_builds(VulkanDevice& device, VkCommandBuffer cmd, std::vector<Build>& builds,
                   const Buffer& scratch) {
  if (builds.empty()) return;
  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> ranges;
  VkDeviceSize alignment = std::max<VkDeviceSize>(
      device.as_properties().minAccelerationStructureScratchOffsetAlignment, 1);
  VkDeviceAddress base = align_up(scratch.address(), alignment);
  for (Build& b : builds) {
    b.info.scratchData.deviceAddress = base + b.scratch_offset;
    infos.push_back(b.info);
    ranges.push_back(b.ranges.data());
  }
  device.rt().cmd_build_acceleration_structures(cmd, static_cast<uint32_t>(infos.size()),
                                                infos.data(), ranges.data());
}

Buffer scratch_buffer(VulkanDevice& device, VkDeviceSize size) {
  VkDeviceSize alignment = std::max<VkDeviceSize>(
      device.as_properties().minAccelerationStructureScratchOffsetAlignment, 1);
  return Buffer(device, size + alignment,
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
}

// Builds, compaction queries and compacting copies all access acceleration structures in the
// ACCELERATION_STRUCTURE_BUILD stage (spec: vkCmdBuildAccelerationStructuresKHR,
// vkCmdWriteAccelerationStructuresPropertiesKHR, vkCmdCopyAccelerationStructureKHR), so one
// barrier orders each step's writes before the next step's reads and writes.
void build_barrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                          VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                       VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
}

class CompactedSizeQueries {
 public:
  CompactedSizeQueries(VulkanDevice& device, uint32_t count) : device_(device), count_(count) {
    VkQueryPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    info.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
    info.queryCount = count;
    vk_check(vkCreateQueryPool(device.handle(), &info, nullptr, &pool_),
             "vkCreateQueryPool (acceleration-structure compacted sizes)");
  }
  ~CompactedSizeQueries() { vkDestroyQueryPool(device_.handle(), pool_, nullptr); }
  CompactedSizeQueries(const CompactedSizeQueries&) = delete;
  CompactedSizeQueries& operator=(const CompactedSizeQueries&) = delete;

  VkQueryPool pool() const { return pool_; }

  // Waits for the queries a completed submission wrote (64-bit results).
  std::vector<VkDeviceSize> results() const {
    std::vector<uint64_t> sizes(count_);
    vk_check(vkGetQueryPoolResults(device_.handle(), pool_, 0, count_,
                                   sizes.size() * sizeof(uint64_t), sizes.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
             "vkGetQueryPoolResults (acceleration-structure compacted sizes)");
    return std::vector<VkDeviceSize>(sizes.begin(), sizes.end());
  }

 private:
  VulkanDevice& device_;
  uint32_t count_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
};

// Builds `built` (prepared from `builds`) and returns the compacted size of each.
std::vector<VkDeviceSize> build_and_query(
    VulkanDevice& device, std::vector<Build>& builds,
    const std::vector<std::unique_ptr<AccelerationStructure>>& built, VkDeviceSize scratch_size) {
  if (built.empty()) return {};
  std::vector<VkAccelerationStructureKHR> handles;
  for (const auto& as : built) handles.push_back(as->handle());
  const uint32_t count = static_cast<uint32_t>(handles.size());
  Buffer scratch = scratch_buffer(device, scratch_size);
  CompactedSizeQueries queries(device, count);
  device.submit_and_wait([&](VkCommandBuffer cmd) {
    // Structures this build reads (the TLAS's BLASes) were written by earlier submissions.
    build_barrier(cmd);
    vkCmdResetQueryPool(cmd, queries.pool(), 0, count);
    record_builds(device, cmd, builds, scratch);
    build_barrier(cmd);
    device.rt().cmd_write_acceleration_structure_properties(
        cmd, count, handles.data(), VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR,
        queries.pool(), 0);
  });
  return queries.results();
}

// Copies each of `built` into a new structure of its compacted size and waits for the copies,
// after which the originals may be freed. `what` names the structures in errors.
std::vector<std::unique_ptr<AccelerationStructure>> compact(
    VulkanDevice& device, VkAccelerationStructureTypeKHR type,
    const std::vector<std::unique_ptr<AccelerationStructure>>& built,
    const std::vector<VkDeviceSize>& sizes, const char* what) {
  std::vector<std::unique_ptr<AccelerationStructure>> compacted;
  for (size_t i = 0; i < built.size(); ++i) {
    // The compacted size is at most the built one (spec, vkCmdCopyAccelerationStructureKHR
    // with the COMPACT mode); zero or a larger size means the query did not report one.
    if (sizes[i] == 0 || sizes[i] > built[i]->size())
      throw GpuError(std::string(what) + " " + std::to_string(i) + ": compacted size " +
                     std::to_string(sizes[i]) + " is outside (0, " +
                     std::to_string(built[i]->size()) + "], the built size");
    compacted.push_back(std::make_unique<AccelerationStructure>(device, type, sizes[i]));
  }
  if (built.empty()) return compacted;
  device.submit_and_wait([&](VkCommandBuffer cmd) {
    build_barrier(cmd);  // the builds were an earlier submission
    for (size_t i = 0; i < built.size(); ++i) {
      VkCopyAccelerationStructureInfoKHR copy{};
      copy.sType = VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR;
      copy.src = built[i]->handle();
      copy.dst = compacted[i]->handle();
      copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
      device.rt().cmd_copy_acceleration_structure(cmd, &copy);
    }
  });
  return compacted;
}

VkDeviceSize total_size(const std::vector<std::unique_ptr<AccelerationStructure>>& structures) {
  VkDeviceSize total = 0;
  for (const auto& as : structures) total += as->size();
  return total;
}

}  // namespace

SceneAccel::SceneAccel(VulkanDevice& device, const SceneBuffers& scene,
                       const GeometryLayout& layout, const Buffer& positions,
                       const Buffer& indices) {
  std::vector<VkAabbPositionsKHR> aabbs;
  for (const GeometryLayout::Entry& e : layout.blases)
    if (e.procedural)
      for (uint32_t s : e.shapes) aabbs.push_back(shape_bounds(scene.shapes[s]));
  Buffer aabb_buffer =
      upload_buffer(device, aabbs.data(), aabbs.size() * sizeof(VkAabbPositionsKHR), kBuildInput);

  std::vector<Build> blas_builds(layout.blases.size());
  std::vector<std::unique_ptr<AccelerationStructure>> built;
  VkDeviceSize scratch_size = 0;
  size_t aabb_index = 0;
  for (size_t b = 0; b < layout.blases.size(); ++b) {
    const GeometryLayout::Entry& e = layout.blases[b];
    Build& build = blas_builds[b];
    for (uint32_t s : e.shapes) {
      const Shape& shape = scene.shapes[s];
      VkAccelerationStructureGeometryKHR g{};
      g.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
      // Alpha-tested meshes leave the opaque bit clear so that shaders/alpha.rahit runs.
      const bool alpha_tested =
          (scene.materials[shape.material].flags & MATERIAL_ALPHA_TESTED) != 0;
      g.flags = alpha_tested ? 0 : VK_GEOMETRY_OPAQUE_BIT_KHR;
      VkAccelerationStructureBuildRangeInfoKHR range{};
      if (e.procedural) {
        g.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
        g.geometry.aabbs.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
        g.geometry.aabbs.data.deviceAddress = aabb_buffer.address();
        g.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
        range.primitiveCount = 1;
        range.primitiveOffset = static_cast<uint32_t>(aabb_index++ * sizeof(VkAabbPositionsKHR));
      } else {
        g.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
        auto& tri = g.geometry.triangles;
        tri.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
        tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
        // Each shape's vertices and indices are addressed directly rather than through
        // primitiveOffset/firstVertex: lavapipe (Mesa 25.0) mis-builds BLASes whose geometries
        // share one vertex buffer through firstVertex (seen on the Cornell box).
        tri.vertexData.deviceAddress =
            positions.address() + VkDeviceAddress(shape.first_vertex) * sizeof(vec4);
        tri.vertexStride = sizeof(vec4);
        tri.maxVertex = std::max<uint32_t>(shape.vertex_count, 1) - 1;
        tri.indexType = VK_INDEX_TYPE_UINT32;
        tri.indexData.deviceAddress =
            indices.address() + VkDeviceAddress(shape.first_index) * sizeof(uint32_t);
        range.primitiveCount = shape.triangle_count;
        range.primitiveOffset = 0;
        range.firstVertex = 0;
        if (static_cast<size_t>(shape.first_index) + 3u * shape.triangle_count >
                scene.indices.size() ||
            static_cast<size_t>(shape.first_vertex) + shape.vertex_count > scene.positions.size())
          throw GpuError("shape " + std::to_string(s) + " indexes past the scene's mesh buffers");
      }
      build.geometries.push_back(g);
      build.ranges.push_back(range);
    }
    built.push_back(
        prepare(device, build, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, scratch_size));
  }
  {
    std::vector<VkDeviceSize> sizes = build_and_query(device, blas_builds, built, scratch_size);
    blases_ =
        compact(device, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, built, sizes, "BLAS");
    memory_.blas_built = total_size(built);
    memory_.blas_compacted = total_size(blases_);
    built.clear();
  }

  std::vector<VkAccelerationStructureInstanceKHR> instances;
  for (size_t b = 0; b < layout.blases.size(); ++b) {
    const Instance& inst = scene.instances[layout.blases[b].instance];
    VkAccelerationStructureInstanceKHR vi{};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) vi.transform.matrix[r][c] = inst.to_world[r][c];
    vi.instanceCustomIndex = layout.blases[b].instance;
    vi.mask = 0xff;
    vi.instanceShaderBindingTableRecordOffset =
        layout.blases[b].procedural ? HIT_GROUP_PROCEDURAL : HIT_GROUP_TRIANGLES;
    bool alpha_tested = false;
    for (uint32_t s : layout.blases[b].shapes)
      alpha_tested |=
          (scene.materials[scene.shapes[s].material].flags & MATERIAL_ALPHA_TESTED) != 0;
    vi.flags = alpha_tested ? 0 : VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR;
    vi.accelerationStructureReference = blases_[b]->address();
    instances.push_back(vi);
  }
  if (layout.blases.size() >= (1u << 24))
    throw GpuError("too many instances for a Vulkan TLAS (24-bit custom index)");
  Buffer instance_buffer =
      upload_buffer(device, instances.data(),
                    instances.size() * sizeof(VkAccelerationStructureInstanceKHR), kBuildInput);

  std::vector<Build> tlas_build(1);
  VkAccelerationStructureGeometryKHR g{};
  g.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
  g.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  g.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  g.geometry.instances.data.deviceAddress = instance_buffer.address();
  tlas_build[0].geometries.push_back(g);
  VkAccelerationStructureBuildRangeInfoKHR range{};
  range.primitiveCount = static_cast<uint32_t>(instances.size());
  tlas_build[0].ranges.push_back(range);
  VkDeviceSize tlas_scratch_size = 0;
  built.push_back(prepare(device, tlas_build[0], VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                          tlas_scratch_size));
  std::vector<VkDeviceSize> sizes = build_and_query(device, tlas_build, built, tlas_scratch_size);
  tlas_ = std::move(
      compact(device, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, built, sizes, "TLAS")[0]);
  memory_.tlas_built = built[0]->size();
  memory_.tlas_compacted = tlas_->size();
}

}  // namespace tr
