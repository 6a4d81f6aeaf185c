// CPU <-> GPU lockstep on the sensor and reconstruction filter scenes of
// validation/mitsuba/sensors (every sensor type, crop windows, sample_border, and each filter,
// the negative-lobed ones included) at 16 spp.
#include <gtest/gtest.h>

#include "lockstep_check.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

class SensorLockstep : public testing::TestWithParam<std::string> {};

TEST_P(SensorLockstep, SixteenSamplesPerPixel) {
  const std::string path = std::string(TWINRAY_SENSOR_SCENES) + "/" + GetParam() + ".xml";
  expect_lockstep(GetParam(), load_scene(path, {}), 16, 31);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SensorLockstep,
                         testing::Values("sensor_perspective", "sensor_thinlens",
                                         "sensor_orthographic", "filter_tent", "filter_mitchell",
                                         "filter_catmullrom", "filter_lanczos"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace tr
