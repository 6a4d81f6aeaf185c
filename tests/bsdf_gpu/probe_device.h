// The compute pipeline of tests/bsdf_gpu/bsdf_probe.comp on the first usable Vulkan device, a
// client of validation/device_batch's ComputeKernel: set 0 holds the scene bindings of
// core/bindings.h (materials, textures and texels filled in, the rest empty), set 1 the queries
// and results.
#ifndef TWINRAY_TESTS_BSDF_GPU_PROBE_DEVICE_H
#define TWINRAY_TESTS_BSDF_GPU_PROBE_DEVICE_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "compute_kernel.h"
#include "core/scene_types.h"
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

  const std::string& device_name() const { return kernel_.device_name(); }

  // Builds the pipeline of `variant`; returns the seconds vkCreateComputePipelines took.
  double build(const ProbeVariant& variant);

  // Evaluates queries[0, count) on the device (with the pipeline of the last build()) into
  // results[0, count).
  void evaluate(const ProbeQuery* queries, std::size_t count, const ProbeScene& scene,
                ProbeResult* results);

 private:
  device_batch::ComputeKernel kernel_;
};

}  // namespace tr::bsdf_gpu

#endif
