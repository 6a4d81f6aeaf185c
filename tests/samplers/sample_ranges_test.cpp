// Any sample range renders alone (issue 11): with each stratified sampler, the Cornell box
// rendered as 16 samples per pixel at once and as the ranges [0, 5) and [5, 16), which split
// a pass, gives the same image bit for bit on the CPU.
#include <gtest/gtest.h>

#include "cpu_backend/render_cpu.h"
#include "scenes/load_scene.h"
#include "scenes/sampler.h"

namespace tr {
namespace {

RenderResult render_ranges(const Scene& scene, std::initializer_list<std::uint32_t> ranges) {
  RenderOptions options;
  options.seed = 3;
  std::unique_ptr<Renderer> renderer = make_cpu_renderer(scene, options);
  const Camera& c = scene.buffers.globals.camera;
  FilmState film = empty_film(c.width, c.height);
  for (std::uint32_t count : ranges) renderer->render(count, film, {});
  return film_result(film, *renderer);
}

TEST(SampleRanges, RenderAloneAndMergeExactly) {
  LoadOptions load;
  load.defines["width"] = "24";
  load.defines["height"] = "24";
  for (uint type : {SAMPLER_STRATIFIED, SAMPLER_LDSAMPLER, SAMPLER_MULTIJITTER, SAMPLER_ORTHOGONAL,
                    SAMPLER_ZSOBOL, SAMPLER_SOBOL}) {
    Scene scene = load_scene(TWINRAY_CORNELL_BOX, load);
    set_sampler(scene, type, 16, true);
    RenderResult whole = render_ranges(scene, {16});
    RenderResult split = render_ranges(scene, {5, 11});
    EXPECT_EQ(whole.mean, split.mean) << sampler_name(type);
    EXPECT_EQ(whole.variance, split.variance) << sampler_name(type);
  }
}

}  // namespace
}  // namespace tr
