#include "gpu_backend/render_gpu.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "gpu_backend/device_info.h"
#include "gpu_backend/gpu_error.h"
#include "gpu_backend/gpu_scene.h"
#include "gpu_backend/rt_pipeline.h"
#include "gpu_backend/variance_merge.h"
#include "gpu_backend/vk_device.h"
#include "gpu_backend/vk_instance.h"
#include "render/pass_size.h"
#include "scenes/scene_features.h"
#include "spirv/aov.h"
#include "spirv/aov_loops.h"
#include "spirv/raygen.h"
#include "spirv/raygen_loops.h"

namespace tr {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The features the pipeline is compiled for (GpuTuning::features).
SceneFeatures pipeline_features(const Scene& scene, const GpuTuning& tuning) {
  const SceneFeatures own = scene_features(scene.buffers);
  if (!tuning.features) return own;
  if (!features_cover(*tuning.features, own))
    throw GpuError("the pipeline's features do not cover the scene's");
  return *tuning.features;
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

// The pipeline's ray-generation shaders (RaygenShader).
const uint32_t kPixelRaygen = 0;
const uint32_t kAovRaygen = 1;

// The Vulkan device, pipeline, scene and buffers of one render, kept across passes.
class GpuRenderer final : public Renderer {
 public:
  GpuRenderer(const Scene& scene, const RenderOptions& options, const RaygenShader& raygen,
              const GpuTuning& tuning)
      : width_(scene.buffers.globals.camera.width),
        height_(scene.buffers.globals.camera.height),
        pixels_(static_cast<size_t>(width_) * height_),
        aov_count_(scene.buffers.globals.integrator.aov_count),
        seed_(options.seed),
        pass_size_(sampler_pass_size(scene.buffers.globals.sampler_params)) {
    if (width_ == 0 || height_ == 0) throw GpuError("the scene's film has no pixels");
    if (aov_count_ > 0 && !raygen.aovs)
      throw GpuError("the scene has AOVs and the ray-generation shader writes none");
    Clock::time_point phase = Clock::now();
    instance_ = std::make_unique<VulkanInstance>();
    const std::vector<DeviceInfo> devices = query_devices(instance_->handle());
    device_info_ = select_device(devices, options.device);
    device_ = std::make_unique<VulkanDevice>(*instance_, device_info_);
    timings_.setup_seconds = seconds_since(phase);
    phase = Clock::now();
    const bool loops = device_info_.cpu || tuning.keep_loops;
    auto build = [loops](const SpirvBuilds& b) {
      return loops ? Spirv{b.cpu, b.cpu_bytes} : Spirv{b.gpu, b.gpu_bytes};
    };
    const SceneFeatures features = pipeline_features(scene, tuning);
    std::vector<Spirv> raygens{build(raygen.pixels)};
    if (features.aov_types != 0u && raygen.aovs) raygens.push_back(build(*raygen.aovs));
    pipeline_ = std::make_unique<RayTracingPipeline>(*device_, raygens, features);
    timings_.pipeline_seconds = seconds_since(phase);
    timings_.raygen_stack_bytes = pipeline_->raygen_stack_size(kPixelRaygen);
    phase = Clock::now();
    batch_bytes_ = pixels_ * sizeof(PixelBatch);
    batches_ = Buffer(*device_, batch_bytes_,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                      VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    // Without AOVs the binding still needs a buffer: one record, never written.
    aov_bytes_ = pixels_ * aov_count_ * sizeof(PixelBatch);
    aov_batches_ = Buffer(*device_, std::max<VkDeviceSize>(aov_bytes_, sizeof(PixelBatch)),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    for (Slot& slot : slots_) {
      slot.commands = std::make_unique<AsyncCommands>(*device_);
      slot.readback =
          Buffer(*device_, batch_bytes_, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
      if (aov_count_ > 0)
        slot.aov_readback =
            Buffer(*device_, aov_bytes_, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                   VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    }
    scene_ = std::make_unique<GpuScene>(*device_, scene.buffers, pipeline_->set_layout(), batches_,
                                        aov_batches_);
    timings_.build_seconds = seconds_since(phase);
    pending_build_seconds_ = timings_.build_seconds;
    batch_size_ = batch_spp(device_info_, pixels_);
  }

  // Batches cover [k B, (k + 1) B) of the sample indices (B = granularity()), cut short at the
  // end of the range and at the multiples of the sampler's pass size, so that no batch
  // straddles a pass (each pass's value is then exact from its batches' means, film_moments.h):
  // a render split on multiples of B dispatches what one render would.
  void render(uint32_t count, FilmState& film, const ProgressFn& progress) override {
    Clock::time_point phase = Clock::now();
    const uint32_t first = film.samples, end = film.samples + count;
    uint32_t submitted = first, merged = first;
    unsigned next = 0, in_flight = 0;
    while (merged < end) {
      // The first dispatch runs alone: lavapipe compiles the shaders in it.
      const unsigned max_in_flight = dispatches_ == 0 ? 1 : 2;
      while (submitted < end && in_flight < max_in_flight) {
        std::uint64_t boundary = (std::uint64_t(submitted) / batch_size_ + 1) * batch_size_;
        if (pass_size_ > 0)
          boundary = std::min(boundary, (std::uint64_t(submitted) / pass_size_ + 1) * pass_size_);
        const uint32_t n = uint32_t(std::min<std::uint64_t>(boundary, end) - submitted);
        submit(slots_[(next + in_flight) % 2], submitted, n);
        submitted += n;
        ++in_flight;
      }
      Slot& slot = slots_[next];
      slot.commands->wait();
      if (dispatches_ == 0) {
        timings_.first_dispatch_seconds = seconds_since(slot.submitted);
        timings_.first_dispatch_spp = slot.sample_count;
      }
      const PixelBatch* batch = static_cast<const PixelBatch*>(slot.readback.mapped());
      merge_batches(batch, merged, slot.sample_count, film.pass_size, film.pixels);
      if (aov_count_ > 0)
        merge_batches(static_cast<const PixelBatch*>(slot.aov_readback.mapped()), merged,
                      slot.sample_count, film.pass_size, film.aovs);
      for (size_t p = 0; p < pixels_; ++p) {
        film.stats.rays += batch[p].rays;
        film.stats.rejected_nonfinite += batch[p].rejected;
      }
      // The AOV pass counts its camera rays in each pixel's first variable.
      if (aov_count_ > 0) {
        const PixelBatch* aovs = static_cast<const PixelBatch*>(slot.aov_readback.mapped());
        for (size_t p = 0; p < pixels_; ++p) film.stats.rays += aovs[p * aov_count_].rays;
      }
      merged += slot.sample_count;
      next = (next + 1) % 2;
      --in_flight;
      ++dispatches_;
      if (progress)
        progress(static_cast<uint64_t>(merged - first) * pixels_,
                 static_cast<uint64_t>(count) * pixels_);
    }
    film.samples = end;
    film.stats.samples += static_cast<uint64_t>(count) * pixels_;
    const double seconds = seconds_since(phase);
    timings_.render_seconds += seconds;
    film.stats.seconds += seconds + pending_build_seconds_;
    pending_build_seconds_ = 0.0;
  }

  uint32_t granularity() const override { return batch_size_; }
  uint32_t pass_size() const override { return pass_size_; }
  std::string backend() const override { return "gpu"; }
  std::string device() const override { return device_->name(); }
  uint32_t seed() const override { return seed_; }
  const GpuTimings& timings() const { return timings_; }

 private:
  struct Slot {
    std::unique_ptr<AsyncCommands> commands;
    Buffer readback;
    Buffer aov_readback;
    uint32_t sample_count = 0;
    Clock::time_point submitted;
  };

  void submit(Slot& slot, uint32_t first_sample, uint32_t count) {
    BatchParams params{};
    params.first_sample = first_sample;
    params.sample_count = count;
    params.seed = seed_;
    slot.sample_count = count;
    slot.submitted = Clock::now();
    slot.commands->submit([&](VkCommandBuffer cmd) {
      // The previous batch's copy must have read `batches_` before this trace overwrites it.
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                           VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 0, nullptr, 0, nullptr,
                           0, nullptr);
      VkDescriptorSet set = scene_->descriptor_set();
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_->layout(), 0,
                              1, &set, 0, nullptr);
      vkCmdPushConstants(cmd, pipeline_->layout(), VK_SHADER_STAGE_RAYGEN_BIT_KHR, 0,
                         sizeof(BatchParams), &params);
      if (aov_count_ > 0) pipeline_->trace(cmd, kAovRaygen, width_, height_);
      pipeline_->trace(cmd, kPixelRaygen, width_, height_);
      VkMemoryBarrier barrier{};
      barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
      barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                           VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
      VkBufferCopy region{0, 0, batch_bytes_};
      vkCmdCopyBuffer(cmd, batches_.handle(), slot.readback.handle(), 1, &region);
      if (aov_count_ > 0) {
        VkBufferCopy aov_region{0, 0, aov_bytes_};
        vkCmdCopyBuffer(cmd, aov_batches_.handle(), slot.aov_readback.handle(), 1, &aov_region);
      }
      barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                           &barrier, 0, nullptr, 0, nullptr);
    });
  }

  uint32_t width_, height_;
  size_t pixels_;
  uint32_t aov_count_;
  uint32_t seed_;
  uint32_t pass_size_;
  DeviceInfo device_info_;
  std::unique_ptr<VulkanInstance> instance_;
  std::unique_ptr<VulkanDevice> device_;
  std::unique_ptr<RayTracingPipeline> pipeline_;
  VkDeviceSize batch_bytes_ = 0;
  Buffer batches_;
  VkDeviceSize aov_bytes_ = 0;
  Buffer aov_batches_;
  Slot slots_[2];
  std::unique_ptr<GpuScene> scene_;
  uint32_t batch_size_ = 1;
  uint64_t dispatches_ = 0;
  double pending_build_seconds_ = 0.0;
  GpuTimings timings_;
};

}  // namespace

RaygenShader renderer_raygen() {
  return RaygenShader{
      SpirvBuilds{spirv_raygen, sizeof(spirv_raygen), spirv_raygen_loops,
                  sizeof(spirv_raygen_loops)},
      SpirvBuilds{spirv_aov, sizeof(spirv_aov), spirv_aov_loops, sizeof(spirv_aov_loops)}};
}

std::unique_ptr<Renderer> make_gpu_renderer(const Scene& scene, const RenderOptions& options) {
  return std::make_unique<GpuRenderer>(scene, options, renderer_raygen(), GpuTuning());
}

RenderResult render_gpu(const Scene& scene, const RenderOptions& options) {
  return render_with_raygen(scene, options, renderer_raygen());
}

RenderResult render_with_raygen(const Scene& scene, const RenderOptions& options,
                                const RaygenShader& raygen, const GpuTuning& tuning,
                                GpuTimings* timings) {
  GpuRenderer renderer(scene, options, raygen, tuning);
  const Camera& camera = scene.buffers.globals.camera;
  RenderResult result =
      render_all(renderer, camera.width, camera.height, options.spp != 0 ? options.spp : scene.spp,
                 options.progress, scene.buffers.globals.integrator.aov_count);
  if (timings) *timings = renderer.timings();
  return result;
}

}  // namespace tr
