#include "cpu_backend/render_cpu.h"

#include <embree3/rtcore_config.h>
#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "cpu_backend/bound_scene.h"
#include "cpu_backend/cpu_kernels.h"
#include "cpu_backend/embree_scene.h"
#include "render/film_state.h"
#include "render/pass_size.h"
#include "scenes/scene_features.h"

namespace tr {
namespace {

constexpr int kTileSize = 16;

std::size_t chosen_kernel(const SceneFeatures& scene, const CpuTuning& tuning) {
  if (!tuning.kernel) return cpu_kernel_index(scene);
  if (*tuning.kernel >= kCpuKernelCount ||
      !features_cover(kCpuKernels[*tuning.kernel].features, scene))
    throw std::invalid_argument("render_cpu: kernel " + std::to_string(*tuning.kernel) +
                                " does not cover the scene's features");
  return *tuning.kernel;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

class CpuRenderer final : public Renderer {
 public:
  CpuRenderer(const Scene& scene, const RenderOptions& options, const CpuTuning& tuning)
      : threads_(options.threads ? int(options.threads) : tbb::info::default_concurrency()),
        limit_(tbb::global_control::max_allowed_parallelism, size_t(threads_)),
        seed_(options.seed),
        pass_size_(sampler_pass_size(scene.buffers.globals.sampler_params)),
        binding_(scene.buffers),
        kernel_(chosen_kernel(scene_features(scene.buffers), tuning)) {
    auto start = std::chrono::steady_clock::now();
    accel_ = std::make_unique<EmbreeScene>(scene.buffers, scene.robust_intersections);
    build_seconds_ = seconds_since(start);
  }

  void render(uint count, FilmState& film, const ProgressFn& progress) override {
    auto start = std::chrono::steady_clock::now();
    const uint first = film.samples;
    const std::uint64_t total = std::uint64_t(film.width) * film.height * count;
    std::atomic<std::uint64_t> done{0};
    std::mutex progress_mutex;
    tbb::combinable<ThreadCounts> counts;
    if (film.pass_size > 0 && !film.pixels.has_passes())
      throw std::logic_error("render_cpu: a film of pass size " + std::to_string(film.pass_size) +
                             " without pass moments (render/film_state.h empty_film)");
    FilmTarget target{film.pixels, film.aovs, film.pass_size, film.pixels.has_negative(), {}};
    tbb::parallel_for(
        tbb::blocked_range2d<uint>(0, film.height, kTileSize, 0, film.width, kTileSize),
        [&](const tbb::blocked_range2d<uint>& tile) {
          ThreadCounts& local = counts.local();
          for (uint y = tile.rows().begin(); y != tile.rows().end(); ++y)
            for (uint x = tile.cols().begin(); x != tile.cols().end(); ++x)
              render_pixel_(*accel_, uvec2(x, y), size_t(y) * film.width + x, first, count, seed_,
                            target, local);
          std::uint64_t now = done +=
              std::uint64_t(tile.rows().size()) * tile.cols().size() * count;
          if (progress) {
            std::unique_lock<std::mutex> lock(progress_mutex, std::try_to_lock);
            if (lock.owns_lock()) progress(now, total);
          }
        });
    counts.combine_each([&](const ThreadCounts& c) {
      film.stats.rays += c.rays;
      film.stats.rejected_nonfinite += c.rejected;
    });
    film.samples += count;
    film.stats.samples += total;
    film.stats.seconds += seconds_since(start) + build_seconds_;
    build_seconds_ = 0.0;
    if (progress) progress(total, total);
  }

  uint granularity() const override { return 1; }
  uint pass_size() const override { return pass_size_; }
  std::string backend() const override { return "cpu"; }
  std::string device() const override {
    return "Embree " + std::string(RTC_VERSION_STRING) + ", " + std::to_string(threads_) +
           (threads_ == 1 ? " thread" : " threads") + ", kernel " + kCpuKernels[kernel_].name +
           (accel_->robust() ? "" : ", traversal not robust");
  }
  uint seed() const override { return seed_; }

 private:
  int threads_;
  tbb::global_control limit_;
  uint seed_;
  uint pass_size_;
  ScopedSceneBinding binding_;
  std::size_t kernel_;
  PixelKernel render_pixel_ = cpu_kernel_entry(kernel_);
  std::unique_ptr<EmbreeScene> accel_;
  double build_seconds_ = 0.0;
};

}  // namespace

std::unique_ptr<Renderer> make_cpu_renderer(const Scene& scene, const RenderOptions& options,
                                            const CpuTuning& tuning) {
  return std::make_unique<CpuRenderer>(scene, options, tuning);
}

RenderResult render_cpu(const Scene& scene, const RenderOptions& options, const CpuTuning& tuning) {
  const Camera& camera = scene.buffers.globals.camera;
  std::unique_ptr<Renderer> renderer = make_cpu_renderer(scene, options, tuning);
  return render_all(*renderer, camera.width, camera.height, options.spp ? options.spp : scene.spp,
                    options.progress, scene.buffers.globals.integrator.aov_count);
}

}  // namespace tr
