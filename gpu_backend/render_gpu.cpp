#include "gpu_backend/render_gpu.h"

#include <algorithm>
#include <chrono>
#include <cstring>

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

// Dispatches aim at this duration, far below any driver watchdog (Windows TDR: 2 s), and
// never exceed kMaxBatch samples per pixel (float Welford inside a batch).
const double kTargetDispatchSeconds = 0.1;
const uint32_t kMaxBatch = 256;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
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
  VulkanDevice device(instance, select_device(devices, options.device));
  timing.setup_seconds = seconds_since(phase);
  phase = Clock::now();
  RayTracingPipeline pipeline(device, raygen, raygen_bytes,
                              tuning.specialize ? scene_features(scene.buffers) : all_features());
  timing.pipeline_seconds = seconds_since(phase);
  phase = Clock::now();

  const VkDeviceSize batch_bytes = pixels * sizeof(PixelBatch);
  Buffer batches(device, batch_bytes,
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  Buffer readback(device, batch_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
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

  MomentAccumulator moments(pixels);
  std::vector<PixelBatch> host_batch(pixels);
  uint32_t batch_size = 1;
  uint32_t done = 0;
  while (done < spp) {
    BatchParams params{};
    params.first_sample = done;
    params.sample_count = std::min(batch_size, spp - done);
    params.seed = options.seed;
    const Clock::time_point dispatch_start = Clock::now();
    device.submit_and_wait([&](VkCommandBuffer cmd) {
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
      vkCmdCopyBuffer(cmd, batches.handle(), readback.handle(), 1, &region);
      barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                           &barrier, 0, nullptr, 0, nullptr);
    });
    const double dispatch_seconds = seconds_since(dispatch_start);
    if (done == 0) {
      timing.first_dispatch_seconds = dispatch_seconds;
      timing.first_dispatch_spp = params.sample_count;
    }
    std::memcpy(host_batch.data(), readback.mapped(), batch_bytes);
    moments.merge(host_batch.data(), params.sample_count);
    for (const PixelBatch& b : host_batch) {
      result.stats.rays += b.rays;
      result.stats.rejected_nonfinite += b.rejected;
    }
    done += params.sample_count;
    if (options.progress)
      options.progress(static_cast<uint64_t>(done) * pixels, static_cast<uint64_t>(spp) * pixels);

    const double per_sample = dispatch_seconds / params.sample_count;
    const double fit = per_sample > 0.0 ? kTargetDispatchSeconds / per_sample : kMaxBatch;
    batch_size = static_cast<uint32_t>(std::clamp(fit, 1.0, static_cast<double>(kMaxBatch)));
  }

  result.mean = moments.mean();
  result.variance = moments.variance();
  result.stats.samples = static_cast<uint64_t>(spp) * pixels;
  timing.render_seconds = seconds_since(phase);
  result.stats.seconds = timing.build_seconds + timing.render_seconds;
  if (timings) *timings = timing;
  return result;
}

}  // namespace tr
