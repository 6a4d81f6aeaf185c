#include "gpu_backend/render_gpu.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>

#include "gpu_backend/device_info.h"
#include "gpu_backend/gpu_error.h"
#include "gpu_backend/gpu_scene.h"
#include "gpu_backend/rt_pipeline.h"
#include "gpu_backend/scene_features.h"
#include "gpu_backend/variance_merge.h"
#include "gpu_backend/vk_device.h"
#include "gpu_backend/vk_instance.h"
#include "spirv/raygen.h"

namespace tr {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Samples per pixel of each dispatch. The float Welford inside a batch rounds differently
// for other batch boundaries, so the schedule depends only on the device type and the image
// size, never on measured times: the same seed gives the same image on every run. A dispatch
// holds about 2^20 samples on a CPU device (lavapipe, ~0.5 Msamples/s: ~2 s) and 2^24 on a
// GPU (H100, ~400 Msamples/s: ~45 ms; a GPU 20x slower still stays under Windows' 2 s
// watchdog), and at most 256 per pixel (float Welford inside a batch).
uint32_t batch_spp(const DeviceInfo& device, size_t pixels) {
  const double samples_per_dispatch = device.cpu ? 1048576.0 : 16777216.0;
  return static_cast<uint32_t>(
      std::clamp(std::floor(samples_per_dispatch / double(pixels)), 1.0, 256.0));
}

}  // namespace

RenderResult render_gpu(const Scene& scene, const RenderOptions& options) {
  return render_with_raygen(scene, options, spirv_raygen, sizeof(spirv_raygen));
}

RenderResult render_with_raygen(const Scene& scene, const RenderOptions& options,
                                const uint32_t* raygen, size_t raygen_bytes,
                                const GpuTuning& tuning, GpuTimings* timings) {
  GpuTimings timing;
  Clock::time_point phase = Clock::now();
  const Camera& camera = scene.buffers.globals.camera;
  const uint32_t width = camera.width;
  const uint32_t height = camera.height;
  if (width == 0 || height == 0) throw GpuError("the scene's film has no pixels");
  const uint32_t spp = options.spp != 0 ? options.spp : scene.spp;
  const size_t pixels = static_cast<size_t>(width) * height;

  VulkanInstance instance;
  const std::vector<DeviceInfo> devices = query_devices(instance.handle());
  const DeviceInfo& device_info = select_device(devices, options.device);
  VulkanDevice device(instance, device_info);
  timing.setup_seconds = seconds_since(phase);
  phase = Clock::now();
  RayTracingPipeline pipeline(device, raygen, raygen_bytes,
                              tuning.specialize ? scene_features(scene.buffers) : all_features());
  timing.pipeline_seconds = seconds_since(phase);
  phase = Clock::now();

  // Two dispatches in flight: while the device renders batch k + 1 the host merges batch k,
  // which the device copied from `batches` into the readback buffer of k's slot.
  const VkDeviceSize batch_bytes = pixels * sizeof(PixelBatch);
  Buffer batches(device, batch_bytes,
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  struct Slot {
    std::unique_ptr<AsyncCommands> commands;
    Buffer readback;
    uint32_t sample_count = 0;
    Clock::time_point submitted;
  };
  Slot slots[2];
  for (Slot& slot : slots) {
    slot.commands = std::make_unique<AsyncCommands>(device);
    slot.readback =
        Buffer(device, batch_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  }
  GpuScene gpu_scene(device, scene.buffers, pipeline.set_layout(), batches);
  timing.build_seconds = seconds_since(phase);
  phase = Clock::now();

  RenderResult result;
  result.width = width;
  result.height = height;
  result.spp = spp;
  result.seed = options.seed;
  result.backend = "gpu";
  result.device = device.name();

  auto submit = [&](Slot& slot, uint32_t first_sample, uint32_t count) {
    BatchParams params{};
    params.first_sample = first_sample;
    params.sample_count = count;
    params.seed = options.seed;
    slot.sample_count = count;
    slot.submitted = Clock::now();
    slot.commands->submit([&](VkCommandBuffer cmd) {
      // The previous batch's copy must have read `batches` before this trace overwrites it.
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                           VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 0, nullptr, 0, nullptr,
                           0, nullptr);
      VkDescriptorSet set = gpu_scene.descriptor_set();
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline.layout(), 0, 1,
                              &set, 0, nullptr);
      vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_RAYGEN_BIT_KHR, 0,
                         sizeof(BatchParams), &params);
      pipeline.trace(cmd, width, height);
      VkMemoryBarrier barrier{};
      barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
      barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                           VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
      VkBufferCopy region{0, 0, batch_bytes};
      vkCmdCopyBuffer(cmd, batches.handle(), slot.readback.handle(), 1, &region);
      barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                           &barrier, 0, nullptr, 0, nullptr);
    });
  };

  MomentAccumulator moments(pixels);
  const uint32_t batch_size = batch_spp(device_info, pixels);
  uint32_t submitted = 0, merged = 0;
  unsigned next = 0, in_flight = 0, completed = 0;
  while (merged < spp) {
    // The first dispatch runs alone: lavapipe compiles the shaders in it.
    const unsigned max_in_flight = completed == 0 ? 1 : 2;
    while (submitted < spp && in_flight < max_in_flight) {
      const uint32_t count = std::min(batch_size, spp - submitted);
      submit(slots[(next + in_flight) % 2], submitted, count);
      submitted += count;
      ++in_flight;
    }
    Slot& slot = slots[next];
    slot.commands->wait();
    if (completed == 0) {
      timing.first_dispatch_seconds = seconds_since(slot.submitted);
      timing.first_dispatch_spp = slot.sample_count;
    }
    const PixelBatch* batch = static_cast<const PixelBatch*>(slot.readback.mapped());
    moments.merge(batch, slot.sample_count);
    for (size_t p = 0; p < pixels; ++p) {
      result.stats.rays += batch[p].rays;
      result.stats.rejected_nonfinite += batch[p].rejected;
    }
    merged += slot.sample_count;
    next = (next + 1) % 2;
    --in_flight;
    ++completed;
    if (options.progress)
      options.progress(static_cast<uint64_t>(merged) * pixels, static_cast<uint64_t>(spp) * pixels);
  }

  moments.develop(result.mean, result.variance);
  result.stats.samples = static_cast<uint64_t>(spp) * pixels;
  timing.render_seconds = seconds_since(phase);
  result.stats.seconds = timing.build_seconds + timing.render_seconds;
  if (timings) *timings = timing;
  return result;
}

}  // namespace tr
