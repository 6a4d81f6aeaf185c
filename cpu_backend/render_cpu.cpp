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

#include "core/integrator.h"
#include "core/integrators/aov.h"
#include "cpu_backend/bound_scene.h"
#include "cpu_backend/embree_scene.h"
#include "render/film_moments.h"
#include "render/film_state.h"
#include "render/pass_size.h"

namespace tr {
namespace {

constexpr int kTileSize = 16;

struct ThreadCounts {
  std::uint64_t rays = 0;
  std::uint64_t rejected = 0;
};

// One render() call's film: accumulator i of `pixels` or `aovs` gets its samples, and the
// negative groups are allocated when the first negative sample arrives (a filter with negative
// lobes, core/film.h), by one thread while the others wait (std::call_once), so that a film
// without negative samples holds none.
struct FilmTarget {
  FilmMomentArray& pixels;
  FilmMomentArray& aovs;
  uint pass_size;
  std::once_flag negative_once;

  void add(FilmMomentArray& a, size_t i, bool negative, const vec3& L) {
    if (negative) {
      std::call_once(negative_once, [this] {
        pixels.keep_negative();
        aovs.keep_negative();
      });
      add_sample(a.negative(i), L);
    } else {
      add_sample(a.positive(i), L);
    }
    if (pass_size > 0u) add_to_pass(a.passes(i), negative ? -1.0 : 1.0, 1.0, L);
  }
};

// Samples [first, first + count) of one pixel, in order, added to its moments in double
// (render/film_moments.h); sample i ends a pass when (i + 1) % pass_size == 0.
// With AOVs (core/integrators/aov.h) the camera ray is traced before the integrator runs, and
// its hit serves the integrator's first step.
void render_pixel(const EmbreeScene& accel, uvec2 pixel, size_t index, uint first, uint count,
                  uint seed, FilmTarget& film, ThreadCounts& counts) {
  const Integrator it = scene_globals().integrator;
  const uint pass_size = film.pass_size;
  for (uint i = first; i < first + count; ++i) {
    PathState s = integrator_begin(pixel, i, seed);
    bool camera_hit_pending = false;
    Hit camera_hit;
    if (it.aov_count > 0u) {
      camera_hit = accel.intersect(s.ray);
      ++counts.rays;
      camera_hit_pending = true;
      AovPoint a = aov_point(s.ray, camera_hit);
      for (uint k = 0; k < it.aov_count; ++k)
        film.add(film.aovs, index * it.aov_count + k, integrator_negative(s),
                 aov_value(scene_aov_type(k), a));
    }
    while (integrator_alive(s)) {
      Hit hit = camera_hit_pending ? camera_hit : accel.intersect(s.ray);
      if (!camera_hit_pending) ++counts.rays;
      camera_hit_pending = false;
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
    film.add(film.pixels, index, integrator_negative(s), L);
    if (pass_size > 0u && (i + 1u) % pass_size == 0u) {
      end_pass(film.pixels.passes(index));
      for (uint k = 0; k < it.aov_count; ++k) end_pass(film.aovs.passes(index * it.aov_count + k));
    }
  }
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

class CpuRenderer final : public Renderer {
 public:
  CpuRenderer(const Scene& scene, const RenderOptions& options)
      : threads_(options.threads ? int(options.threads) : tbb::info::default_concurrency()),
        limit_(tbb::global_control::max_allowed_parallelism, size_t(threads_)),
        seed_(options.seed),
        pass_size_(sampler_pass_size(scene.buffers.globals.sampler_params)),
        binding_(scene.buffers) {
    auto start = std::chrono::steady_clock::now();
    accel_ = std::make_unique<EmbreeScene>(scene.buffers);
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
    FilmTarget target{film.pixels, film.aovs, film.pass_size, {}};
    tbb::parallel_for(
        tbb::blocked_range2d<uint>(0, film.height, kTileSize, 0, film.width, kTileSize),
        [&](const tbb::blocked_range2d<uint>& tile) {
          ThreadCounts& local = counts.local();
          for (uint y = tile.rows().begin(); y != tile.rows().end(); ++y)
            for (uint x = tile.cols().begin(); x != tile.cols().end(); ++x)
              render_pixel(*accel_, uvec2(x, y), size_t(y) * film.width + x, first, count, seed_,
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
           (threads_ == 1 ? " thread" : " threads");
  }
  uint seed() const override { return seed_; }

 private:
  int threads_;
  tbb::global_control limit_;
  uint seed_;
  uint pass_size_;
  ScopedSceneBinding binding_;
  std::unique_ptr<EmbreeScene> accel_;
  double build_seconds_ = 0.0;
};

}  // namespace

std::unique_ptr<Renderer> make_cpu_renderer(const Scene& scene, const RenderOptions& options) {
  return std::make_unique<CpuRenderer>(scene, options);
}

RenderResult render_cpu(const Scene& scene, const RenderOptions& options) {
  const Camera& camera = scene.buffers.globals.camera;
  std::unique_ptr<Renderer> renderer = make_cpu_renderer(scene, options);
  return render_all(*renderer, camera.width, camera.height, options.spp ? options.spp : scene.spp,
                    options.progress, scene.buffers.globals.integrator.aov_count);
}

}  // namespace tr
