// The compute pipeline of tests/bsdf_gpu/bsdf_probe.comp on the first usable Vulkan device:
// set 0 holds the scene bindings of core/bindings.h (materials, textures and texels filled in,
// the rest empty), set 1 the queries and results.
#ifndef TWINRAY_TESTS_BSDF_GPU_PROBE_DEVICE_H
#define TWINRAY_TESTS_BSDF_GPU_PROBE_DEVICE_H

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/scene_types.h"
#include "gpu_backend/vk_device.h"
#include "gpu_backend/vk_instance.h"
#include "probe.h"

namespace tr::bsdf_gpu {

// The specialization of the probe: the feature masks of shaders/features.glsl and the broken
// variant's switch.
struct ProbeVariant {
  uint32_t bsdf_types = 0;      // bit BSDF_*
  uint32_t texture_types = 0;   // bit TEXTURE_*
  uint32_t material_flags = 0;  // MATERIAL_*
  bool pdf_off_by_cosine = false;
};

struct ProbeScene {
  const std::vector<Material>* materials;
  const std::vector<Texture>* textures;
  const std::vector<vec4>* texels;
};

class ProbeDevice {
 public:
  // Throws GpuError naming what is missing when no Vulkan device is usable.
  ProbeDevice();
  ~ProbeDevice();
  ProbeDevice(const ProbeDevice&) = delete;
  ProbeDevice& operator=(const ProbeDevice&) = delete;

  const std::string& device_name() const { return device_->name(); }

  // Builds the pipeline of `variant`; returns the seconds vkCreateComputePipelines took.
  double build(const ProbeVariant& variant);

  // Evaluates every query on the device (with the pipeline of the last build()) into
  // results[0, queries.size()).
  void evaluate(const std::vector<ProbeQuery>& queries, const ProbeScene& scene,
                ProbeResult* results);

 private:
  void dispatch(uint32_t count, const Buffer& materials, const Buffer& textures,
                const Buffer& texels);
  void destroy_pipeline();
  std::unique_ptr<VulkanInstance> instance_;
  std::unique_ptr<VulkanDevice> device_;
  VkDescriptorSetLayout scene_layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout io_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  Buffer empty_;  // every scene binding the probe does not read
  Buffer query_buffer_, result_buffer_;
  std::size_t io_capacity_ = 0;  // queries they hold
};

}  // namespace tr::bsdf_gpu

#endif
