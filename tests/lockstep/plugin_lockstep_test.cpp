// CPU <-> GPU lockstep on the BSDF adapter scenes of validation/mitsuba/plugins at 16 spp.
#include <gtest/gtest.h>

#include "lockstep_check.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

class PluginLockstep : public testing::TestWithParam<std::string> {};

TEST_P(PluginLockstep, SixteenSamplesPerPixel) {
  const std::string path = std::string(TWINRAY_PLUGIN_SCENES) + "/" + GetParam() + ".xml";
  expect_lockstep(GetParam(), load_scene(path, {}), 16, 37);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PluginLockstep,
                         testing::Values("blendbsdf", "normalmap", "bumpmap"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace tr
