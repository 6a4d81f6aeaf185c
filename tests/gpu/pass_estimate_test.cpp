// The error estimate of correlated samplers on the GPU backend (render/error_estimate.h): its
// batches stop at the sampler's pass ends, a render split on batch boundaries keeps the pass
// moments of an unsplit one bit for bit (so a resumed render is the uninterrupted one), and the
// pass estimate agrees with the CPU's, which draws the same numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "cpu_backend/render_cpu.h"
#include "gpu_backend/render_gpu.h"
#include "scenes/load_scene.h"
#include "scenes/sampler.h"

namespace tr {
namespace {

Scene cornell_box(uint sampler, uint requested) {
  LoadOptions load;
  load.defines = {{"width", "8"}, {"height", "8"}, {"max_depth", "3"}};
  Scene scene = load_scene(
      std::string(TWINRAY_SOURCE_DIR) + "/examples/scenes/cornell-box/cornell_box.xml", load);
  set_sampler(scene, sampler, requested, true);
  return scene;
}

void expect_same_moments(const FilmState& a, const FilmState& b) {
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  ASSERT_EQ(a.pixels.has_negative(), b.pixels.has_negative());
  for (std::size_t p = 0; p < a.pixels.size(); ++p) {
    const FilmMoments x = a.pixels.at(p, a.samples), y = b.pixels.at(p, b.samples);
    ASSERT_EQ(std::memcmp(&x, &y, sizeof(FilmMoments)), 0) << p;
  }
}

FilmState render_ranges(Renderer& renderer, const std::vector<uint32_t>& ranges) {
  FilmState film = empty_film(8, 8, 0, renderer.pass_size());
  for (uint32_t count : ranges) renderer.render(count, film, {});
  return film;
}

// lavapipe's batches at 8x8 are 256 spp: passes of 512 take two.
TEST(GpuPassEstimate, SplitOnBatchesKeepsThePassMomentsBitForBit) {
  const Scene scene = cornell_box(SAMPLER_ZSOBOL, 512);
  RenderOptions options;
  options.seed = 4;
  std::unique_ptr<Renderer> gpu = make_gpu_renderer(scene, options);
  ASSERT_EQ(gpu->pass_size(), 512u);
  const uint32_t g = gpu->granularity();
  ASSERT_LT(g, 512u);
  const FilmState whole = render_ranges(*gpu, {1024});
  const FilmState split = render_ranges(*gpu, {g, 512 - g, 512});
  ASSERT_EQ(whole.pixels.at(0, whole.samples).passes.values.n, 2.0);
  expect_same_moments(whole, split);

  // The CPU draws the same numbers: the estimates agree up to float rounding.
  std::unique_ptr<Renderer> cpu_renderer = make_cpu_renderer(scene, options);
  const FilmState cpu = render_ranges(*cpu_renderer, {1024});
  std::vector<double> gpu_mean, gpu_var, cpu_mean, cpu_var;
  develop_film(whole, gpu_mean, gpu_var);
  develop_film(cpu, cpu_mean, cpu_var);
  double gpu_sum = 0.0, cpu_sum = 0.0;
  for (std::size_t i = 0; i < gpu_var.size(); ++i) {
    gpu_sum += gpu_var[i];
    cpu_sum += cpu_var[i];
  }
  EXPECT_NEAR(gpu_sum, cpu_sum, 1e-3 * cpu_sum);
}

// Orthogonal passes of 17^2 = 289 with batches of 256: the batches [0, 256), [256, 289),
// [289, 512), [512, 578) stop at the pass end, and a split on a batch boundary renders them
// alike.
TEST(GpuPassEstimate, BatchesStopAtPassEnds) {
  const Scene scene = cornell_box(SAMPLER_ORTHOGONAL, 289);
  std::unique_ptr<Renderer> renderer = make_gpu_renderer(scene, RenderOptions{});
  EXPECT_EQ(renderer->pass_size(), 289u);
  ASSERT_EQ(renderer->granularity(), 256u) << "the batch no longer depends on the pass";
  const FilmState whole = render_ranges(*renderer, {289 * 2});
  const FilmState split = render_ranges(*renderer, {256, 289 * 2 - 256});
  EXPECT_EQ(whole.pixels.at(0, whole.samples).passes.values.n, 2.0);
  expect_same_moments(whole, split);
}

}  // namespace
}  // namespace tr
