// CPU <-> GPU lockstep of the stratified samplers, zsobol and sobol (issue 11): the Cornell box
// (48x48) with each sampler at 16 spp (orthogonal: 25), so that every draw of the path goes
// through core/samplers/ on both sides. Without jitter the points sit at strata centers,
// symmetric in x and y, so on the Cornell box the camera rays of pixels on the image diagonals
// hit the diagonal edges of its quads exactly and Embree and the GPU split those ties
// differently (1.9% of the pixels): that case renders the textured_diffuse scene of the Mitsuba
// suite instead.
#include <gtest/gtest.h>

#include "lockstep_check.h"
#include "scenes/load_scene.h"
#include "scenes/sampler.h"
#include "validation/harness/scene_render.h"
#include "validation/harness/suite.h"

namespace tr {
namespace {

Scene cornell_box(uint sampler) {
  LoadOptions load;
  load.defines["width"] = "48";
  load.defines["height"] = "48";
  Scene scene = load_scene(TWINRAY_CORNELL_BOX, load);
  set_sampler(scene, sampler, 16, true);
  return scene;
}

TEST(SamplerLockstep, Stratified) {
  expect_lockstep("stratified", cornell_box(SAMPLER_STRATIFIED), 16, 31);
}
TEST(SamplerLockstep, StratifiedWithoutJitter) {
  const std::vector<SuiteEntry> suite = read_suite(TWINRAY_MITSUBA_SUITE);
  Scene scene = load_entry_scene(find_entry(suite, "textured_diffuse"));
  set_sampler(scene, SAMPLER_STRATIFIED, 16, false);
  expect_lockstep("stratified, jitter off", scene, 16, 32);
}
TEST(SamplerLockstep, Ldsampler) {
  expect_lockstep("ldsampler", cornell_box(SAMPLER_LDSAMPLER), 16, 33);
}
TEST(SamplerLockstep, Orthogonal) {  // 16 spp rounds up to 25 (5^2)
  Scene scene = cornell_box(SAMPLER_ORTHOGONAL);
  expect_lockstep("orthogonal", scene, scene.spp, 35);
}
TEST(SamplerLockstep, Multijitter) {
  expect_lockstep("multijitter", cornell_box(SAMPLER_MULTIJITTER), 16, 34);
}
TEST(SamplerLockstep, Zsobol) { expect_lockstep("zsobol", cornell_box(SAMPLER_ZSOBOL), 16, 36); }
TEST(SamplerLockstep, Sobol) { expect_lockstep("sobol", cornell_box(SAMPLER_SOBOL), 16, 37); }

}  // namespace
}  // namespace tr
