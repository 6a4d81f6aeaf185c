#include "cpu_backend/render_cpu.h"

#include <embree3/rtcore_config.h>
#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

#include "core/integrator.h"
#include "cpu_backend/bound_scene.h"
#include "cpu_backend/embree_scene.h"
#include "render/film_moments.h"

namespace tr {
namespace {

constexpr int kTileSize = 16;

struct ThreadCounts {
  std::uint64_t rays = 0;
  std::uint64_t rejected = 0;
};

// All samples of one pixel, in order, accumulated in double (render/film_moments.h).
FilmMoments render_pixel(const EmbreeScene& accel, uvec2 pixel, uint spp, uint seed,
                         ThreadCounts& counts) {
  FilmMoments m;
  for (uint i = 0; i < spp; ++i) {
    PathState s = integrator_begin(pixel, i, seed);
    while (integrator_alive(s)) {
      Hit hit = accel.intersect(s.ray);
      ++counts.rays;
      ShadowRay sr = integrator_step(s, hit);
      if (sr.enabled != 0u) {
        ++counts.rays;
        if (!accel.occluded(sr.ray)) integrator_add_unoccluded(s, sr);
      }
    }
    vec3 L = integrator_result(s);
    if (!radiance_is_finite(L)) {
      ++counts.rejected;
      L = vec3(0.0f);
    }
    add_sample(integrator_negative(s) ? m.negative : m.positive, L);
  }
  return m;
}

}  // namespace

RenderResult render_cpu(const Scene& scene, const RenderOptions& options) {
  const SceneBuffers& buffers = scene.buffers;
  const Camera& camera = buffers.globals.camera;
  RenderResult result;
  result.width = camera.width;
  result.height = camera.height;
  result.spp = options.spp ? options.spp : scene.spp;
  result.seed = options.seed;
  result.backend = "cpu";
  result.mean.assign(size_t(result.width) * result.height * 3, 0.0);
  result.variance.assign(result.mean.size(), 0.0);

  int threads = options.threads ? int(options.threads) : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  result.device = "Embree " + std::string(RTC_VERSION_STRING) + ", " + std::to_string(threads) +
                  (threads == 1 ? " thread" : " threads");

  auto start = std::chrono::steady_clock::now();
  ScopedSceneBinding binding(buffers);
  EmbreeScene accel(buffers);

  const std::uint64_t total = std::uint64_t(result.width) * result.height * result.spp;
  std::atomic<std::uint64_t> done{0};
  std::mutex progress_mutex;
  tbb::combinable<ThreadCounts> counts;
  const uint spp = result.spp;
  const uint seed = result.seed;

  tbb::parallel_for(
      tbb::blocked_range2d<uint>(0, result.height, kTileSize, 0, result.width, kTileSize),
      [&](const tbb::blocked_range2d<uint>& tile) {
        ThreadCounts& local = counts.local();
        for (uint y = tile.rows().begin(); y != tile.rows().end(); ++y) {
          for (uint x = tile.cols().begin(); x != tile.cols().end(); ++x) {
            FilmMoments m = render_pixel(accel, uvec2(x, y), spp, seed, local);
            size_t base = (size_t(y) * result.width + x) * 3;
            develop(m, &result.mean[base], &result.variance[base]);
          }
        }
        std::uint64_t now = done += std::uint64_t(tile.rows().size()) * tile.cols().size() * spp;
        if (options.progress) {
          std::unique_lock<std::mutex> lock(progress_mutex, std::try_to_lock);
          if (lock.owns_lock()) options.progress(now, total);
        }
      });

  counts.combine_each([&](const ThreadCounts& c) {
    result.stats.rays += c.rays;
    result.stats.rejected_nonfinite += c.rejected;
  });
  result.stats.samples = total;
  result.stats.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.progress) options.progress(total, total);
  return result;
}

}  // namespace tr
