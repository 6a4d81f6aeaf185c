// The error estimate of correlated samplers (render/error_estimate.h) on the CPU backend: a render
// split into sample ranges keeps the pass moments of an unsplit one bit for bit, a checkpoint
// keeps them, and the estimated variance of a pixel's value agrees with the variance observed
// over independent seeds, where the per-sample variance over n does not.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "cpu_backend/render_cpu.h"
#include "render/checkpoint.h"
#include "render/error_estimate.h"
#include "scenes/load_scene.h"
#include "scenes/sampler.h"

namespace tr::test {
namespace {

// The Cornell box at 16x16 (max_depth 2: direct light, few dimensions, where stratification
// pays most; 0: the scene's own).
Scene cornell_box(uint sampler, uint requested, int max_depth = 0) {
  LoadOptions load;
  load.defines = {{"width", "16"}, {"height", "16"}};
  if (max_depth > 0) load.defines["max_depth"] = std::to_string(max_depth);
  Scene scene = load_scene(
      std::string(TWINRAY_SOURCE_DIR) + "/examples/scenes/cornell-box/cornell_box.xml", load);
  set_sampler(scene, sampler, requested, true);
  return scene;
}

FilmState render_ranges(const Scene& scene, const std::vector<uint>& ranges, uint seed) {
  RenderOptions options;
  options.seed = seed;
  std::unique_ptr<Renderer> renderer = make_cpu_renderer(scene, options);
  const Camera& camera = scene.buffers.globals.camera;
  FilmState film = empty_film(camera.width, camera.height, 0, renderer->pass_size());
  for (uint count : ranges) renderer->render(count, film, {});
  return film;
}

void expect_same_moments(const FilmState& a, const FilmState& b) {
  ASSERT_EQ(a.samples, b.samples);
  ASSERT_EQ(a.pass_size, b.pass_size);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  ASSERT_EQ(a.pixels.has_negative(), b.pixels.has_negative());
  for (std::size_t p = 0; p < a.pixels.size(); ++p) {
    const FilmMoments x = a.pixels.at(p, a.samples), y = b.pixels.at(p, b.samples);
    ASSERT_EQ(std::memcmp(&x, &y, sizeof(FilmMoments)), 0) << "pixel " << p;
  }
}

// Ranges that end inside passes and span several, against one range (passes of 16).
TEST(PassEstimate, SplitRendersKeepThePassMomentsBitForBit) {
  for (uint sampler : {SAMPLER_STRATIFIED, SAMPLER_ZSOBOL}) {
    const Scene scene = cornell_box(sampler, 16);
    const FilmState whole = render_ranges(scene, {64}, 3);
    ASSERT_EQ(whole.pass_size, 16u) << sampler_name(sampler);
    EXPECT_EQ(whole.pixels.at(0, whole.samples).passes.values.n, 4.0);
    expect_same_moments(whole, render_ranges(scene, {5, 11, 27, 1, 20}, 3));
  }
}

TEST(PassEstimate, IndependentHasNoPasses) {
  const FilmState film = render_ranges(cornell_box(SAMPLER_INDEPENDENT, 16), {32}, 1);
  EXPECT_EQ(film.pass_size, 0u);
  EXPECT_EQ(film.pixels.at(0, film.samples).passes.values.n, 0.0);
  // Nor does the film hold any, or negative groups for its gaussian filter (FilmMomentArray).
  EXPECT_FALSE(film.pixels.has_passes());
  EXPECT_FALSE(film.pixels.has_negative());
}

// A checkpoint taken inside a pass resumes to the unsplit render's moments; one of format
// version 1 (without the pass moments), or one whose pixel counts disagree, is refused.
TEST(PassEstimate, CheckpointKeepsThePassMoments) {
  const Scene scene = cornell_box(SAMPLER_ZSOBOL, 16);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("pass_estimate_" + std::to_string(getpid()));
  RenderIdentity id;
  id.build = "test";
  id.scene = "cornell";
  id.backend = "cpu";
  id.seed = 5;
  id.width = id.height = 16;
  id.pass_size = 16;
  RenderOptions options;
  options.seed = 5;
  std::unique_ptr<Renderer> renderer = make_cpu_renderer(scene, options);
  FilmState film = empty_film(16, 16, 0, renderer->pass_size());
  renderer->render(40, film, {});
  write_checkpoint(path.string(), id, film);
  FilmState resumed = read_checkpoint(path.string(), id);
  EXPECT_EQ(resumed.pixels.at(7, resumed.samples).passes.values.n, 2.0);
  EXPECT_NE(resumed.pixels.at(7, resumed.samples).passes.signs, 0.0);
  expect_same_moments(film, resumed);
  renderer->render(24, resumed, {});
  expect_same_moments(render_ranges(scene, {64}, 5), resumed);

  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  // The film stores no positive count (render/film_state.h): a pixel whose counts do not add up
  // to the checkpoint's samples is damage.
  std::string miscounted = bytes;
  const double wrong_count = 39.0;
  miscounted.replace(miscounted.find("end\n") + 4, sizeof wrong_count,
                     reinterpret_cast<const char*>(&wrong_count), sizeof wrong_count);
  std::string version_1 = bytes;
  version_1.replace(0, version_1.find('\n'), "twinray checkpoint 1");
  for (const auto& [damaged, message] :
       {std::pair{miscounted, "do not add up to 40"}, std::pair{version_1, "format version 1"}}) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << damaged;
    try {
      read_checkpoint(path.string(), id);
      ADD_FAILURE() << "a checkpoint was read, expected: " << message;
    } catch (const CheckpointError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove(path);
}

// Calibration. R = 16 renders of other seeds of the direct-lit Cornell box, each K = 16 passes
// of S = 25 orthogonal-array samples; pixels are independent (each has its own hashes and draws
// its own filter samples, core/film.h). For every pixel i (green channel) with sigma_i^2 = the
// mean over the seeds of the estimated variance of its value, t_i = (the variance of its value
// observed over the seeds) / sigma_i^2 has mean 1 if the estimate is right (up to the
// O(1 / (R (K - 1))) bias of 1 / sigma_i^2, about 1%), and the t_i are independent, so their
// mean Q is about normal (central limit theorem over the N ~ 250 pixels that are not noiseless)
// with the standard error sd(t) / sqrt(N), measured. The test asks |Q - 1| <= z se with
// z = 3.29: significance level 0.1% (two-sided). Over 30 runs of other seeds (Q - 1) / se had mean
// 0.18 and sd 0.87, all within +-2.1. The per-sample variance over n, the estimate before passes,
// overstates the error of the stratified mean almost threefold (Q about 0.37, 30 standard errors
// off): the test asserts that it would fail by a wide margin.
struct Calibration {
  double q = 0.0, se = 0.0;  // the mean of t_i and its standard error
  std::size_t pixels = 0;
};

Calibration calibrate(const std::vector<std::vector<double>>& values,
                      const std::vector<std::vector<double>>& estimates) {
  const std::size_t seeds = values.size(), n = values[0].size();
  std::vector<double> t;
  for (std::size_t i = 0; i < n; ++i) {
    double mean = 0.0, estimate = 0.0;
    for (std::size_t r = 0; r < seeds; ++r) {
      mean += values[r][i] / double(seeds);
      estimate += estimates[r][i] / double(seeds);
    }
    if (!(estimate > 1e-12 * (mean * mean + 1e-6))) continue;  // noiseless (the light)
    double observed = 0.0;
    for (std::size_t r = 0; r < seeds; ++r)
      observed += (values[r][i] - mean) * (values[r][i] - mean) / double(seeds - 1);
    t.push_back(observed / estimate);
  }
  Calibration c;
  c.pixels = t.size();
  for (double x : t) c.q += x / double(t.size());
  double squares = 0.0;
  for (double x : t) squares += (x - c.q) * (x - c.q);
  c.se = std::sqrt(squares / double(t.size() - 1) / double(t.size()));
  return c;
}

TEST(PassEstimate, EstimatedVarianceOfTheMeanMatchesTheVarianceOverSeeds) {
  constexpr uint kSeeds = 16, kPasses = 16;
  constexpr double kZ = 3.29;  // two-sided, 0.1%
  const Scene scene = cornell_box(SAMPLER_ORTHOGONAL, 25, 2);
  const uint spp = kPasses * scene.buffers.globals.sampler_params.sample_count;
  std::vector<std::vector<double>> values, passes, per_sample;
  for (uint seed = 1; seed <= kSeeds; ++seed) {
    const FilmState film = render_ranges(scene, {spp}, 1000 + seed);
    ASSERT_EQ(completed_passes(film.pass_size, film.samples), kPasses);
    std::vector<double> v, e, s;
    for (std::size_t p = 0; p < film.pixels.size(); ++p) {
      const FilmMoments m = film.pixels.at(p, film.samples);
      double mean[3], variance[3], ps_mean[3], ps_variance[3];
      develop_estimate(m, film.pass_size, mean, variance);
      develop(m, ps_mean, ps_variance);
      v.push_back(mean[1]);
      e.push_back(variance[1] / spp);
      s.push_back(ps_variance[1] / spp);
    }
    values.push_back(v);
    passes.push_back(e);
    per_sample.push_back(s);
  }
  const Calibration c = calibrate(values, passes), ps = calibrate(values, per_sample);
  std::printf(
      "pixels %zu: observed / estimated variance of the mean: passes %.3f +- %.3f, "
      "per-sample %.3f +- %.3f\n",
      c.pixels, c.q, c.se, ps.q, ps.se);
  ASSERT_GT(c.pixels, 200u);
  EXPECT_LE(std::abs(c.q - 1.0), kZ * c.se) << "the pass estimate is off";
  EXPECT_GT(std::abs(ps.q - 1.0), 3.0 * kZ * ps.se) << "the per-sample estimate would pass";
}

}  // namespace
}  // namespace tr::test
