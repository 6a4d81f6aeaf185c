// pbrt-v4's `ambientocclusion` integrator (core/integrators/ambient_occlusion.h) on the CPU
// against the closed form between two parallel planes (tests/cpu/ambient_occlusion_check.h):
// both sampling strategies, occluders within and beyond maxdistance, the hit seen on the
// floor and on the ceiling whose normal faces away from the camera.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "ambient_occlusion_check.h"
#include "constant_image_check.h"
#include "render_fixture.h"

namespace tr::test {
namespace {

struct AoCase {
  bool cos_sample;
  double max_distance;
  int target;  // z of the look-at target: 0 the floor, 1 the ceiling
};

class AmbientOcclusionPlanes : public testing::TestWithParam<AoCase> {};

TEST_P(AmbientOcclusionPlanes, MatchesTheClosedForm) {
  const AoCase c = GetParam();
  LoadOptions load;
  load.defines = {{"cossample", c.cos_sample ? "true" : "false"},
                  {"maxdistance", std::to_string(c.max_distance)},
                  {"target", std::to_string(c.target)}};
  RenderOptions options;
  options.seed = 1;
  RenderResult r = render_file(test_scene("ambient_occlusion_planes.xml"), options, load);
  expect_constant_image(r, ambient_occlusion_between_planes(1.0, c.max_distance),
                        "cpu cossample " + std::to_string(c.cos_sample) + " maxdistance " +
                            std::to_string(c.max_distance) + " target " + std::to_string(c.target));
}

// Camera rays that hit nothing score 0, as pbrt-v4's AOIntegrator::Li returns L = 0.
TEST(AmbientOcclusion, MissScoresZero) {
  LoadOptions load;
  load.defines = {{"origin", "2"}, {"target", "3"}};
  RenderOptions options;
  options.seed = 1;
  RenderResult r = render_file(test_scene("ambient_occlusion_planes.xml"), options, load);
  expect_constant_image(r, 0.0, "cpu camera rays that miss");
}

// Names such as cosine_R2_floor, for ctest.
std::string case_name(const testing::TestParamInfo<AoCase>& info) {
  const AoCase& c = info.param;
  std::string r = std::to_string(c.max_distance);
  r.erase(r.find_last_not_of('0') + 1);
  if (r.back() == '.') r.pop_back();
  std::replace(r.begin(), r.end(), '.', 'p');
  return std::string(c.cos_sample ? "cosine" : "uniform") + "_R" + r +
         (c.target == 0 ? "_floor" : "_ceiling");
}

INSTANTIATE_TEST_SUITE_P(Cases, AmbientOcclusionPlanes,
                         testing::Values(AoCase{true, 2.0, 0}, AoCase{false, 2.0, 0},
                                         AoCase{true, 0.5, 0}, AoCase{false, 0.5, 0},
                                         AoCase{true, 2.0, 1}, AoCase{false, 2.0, 1},
                                         AoCase{true, 1.25, 0}, AoCase{false, 1.25, 1}),
                         case_name);

}  // namespace
}  // namespace tr::test
