// A compute shader on a Vulkan device that maps an array of queries to an array of results, one
// invocation per query: the device half of validation/device_batch (README.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu_backend/vk_device.h"
#include "gpu_backend/vk_instance.h"
#include "gpu_backend/vulkan_api.h"

namespace tr::device_batch {

struct Binding {
  uint32_t set = 0;
  uint32_t binding = 0;
  bool operator<(const Binding& o) const {
    return set != o.set ? set < o.set : binding < o.binding;
  }
};

// What the shader declares. Every binding is a storage buffer; the push constants are
// `uint first; uint count;` and invocation gl_GlobalInvocationID.x answers query first + x when
// that is below count.
struct KernelLayout {
  std::vector<std::vector<uint32_t>> sets;  // the bindings of set 0, 1, ...
  Binding queries, results;                 // two of them: the query and the result arrays
  uint32_t workgroup_size = 64;             // local_size_x
};

// A specialization constant (constant_id = id) set to a 32-bit value.
struct Specialization {
  uint32_t id;
  uint32_t value;
};

class ComputeKernel {
 public:
  // Opens the device `selector` names ("" the first usable one, an index or a name substring, as
  // `twinray render --device`) with the Khronos validation layer when TWINRAY_VK_VALIDATION=1, and
  // loads `spirv` (`spirv_bytes` long). `label` names the shader in errors. Throws GpuError.
  ComputeKernel(const uint32_t* spirv, std::size_t spirv_bytes, KernelLayout layout,
                const std::string& selector, std::string label);
  ~ComputeKernel();
  ComputeKernel(const ComputeKernel&) = delete;
  ComputeKernel& operator=(const ComputeKernel&) = delete;

  const std::string& device_name() const { return device_->name(); }

  // (Re)creates the pipeline with these specialization constants; returns the seconds
  // vkCreateComputePipelines took.
  double build(const std::vector<Specialization>& constants = {});

  // Copies `bytes` of `data` into the buffer at `at` (a binding other than the query and result
  // arrays), where evaluate() calls find them until the next fill. A binding never filled holds
  // 16 zero bytes.
  void fill(Binding at, const void* data, std::size_t bytes);
  template <typename T>
  void fill(Binding at, const std::vector<T>& values) {
    fill(at, values.data(), values.size() * sizeof(T));
  }

  // Runs the pipeline of the last build() over `count` queries of `query_size` bytes each into
  // `count` results of `result_size` bytes, in as many submissions as the device's buffer and
  // dispatch limits ask for; then fails on any validation error.
  void evaluate(const void* queries, std::size_t query_size, void* results, std::size_t result_size,
                std::size_t count);
  template <typename Query, typename Result>
  void evaluate(const Query* queries, std::size_t count, Result* results) {
    evaluate(queries, sizeof(Query), results, sizeof(Result), count);
  }

 private:
  void write_descriptors();
  std::unique_ptr<VulkanInstance> instance_;
  std::unique_ptr<VulkanDevice> device_;
  KernelLayout layout_;
  std::string label_;
  VkPhysicalDeviceLimits limits_{};
  std::vector<VkDescriptorSetLayout> set_layouts_;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets_;
  std::map<Binding, Buffer> buffers_;  // filled bindings and the query and result arrays
  Buffer empty_;                       // every other binding
  bool descriptors_stale_ = true;      // a buffer was replaced since the last write
};

}  // namespace tr::device_batch
