// CPU <-> GPU lockstep on every scene of the Mitsuba test suite (issue 4), at 1 and 64 spp with
// the suite's seed, or at 1 and the entry's lockstep_spp where it names one (the plugin scenes
// whose acceptance is lockstep at 16 spp). (`twinray validate --gpu`, ctest mitsuba_gpu.*,
// checks them at the suite's spp or lockstep_spp.)
#include <gtest/gtest.h>

#include "lockstep_check.h"
#include "validation/harness/scene_render.h"
#include "validation/harness/suite.h"

namespace tr {
namespace {

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const SuiteEntry& e : read_suite(TWINRAY_MITSUBA_SUITE)) names.push_back(e.name);
  return names;
}

class MitsubaLockstep : public testing::TestWithParam<std::string> {};

TEST_P(MitsubaLockstep, OneAndSixtyFourSamplesPerPixel) {
  const std::vector<SuiteEntry> suite = read_suite(TWINRAY_MITSUBA_SUITE);
  const SuiteEntry& e = find_entry(suite, GetParam());
  Scene scene = load_entry_scene(e);
  expect_lockstep(e.name, scene, 1, entry_seed(e, scene));
  expect_lockstep(e.name, scene, e.lockstep_spp > 0 ? e.lockstep_spp : 64, entry_seed(e, scene));
}

INSTANTIATE_TEST_SUITE_P(Suite, MitsubaLockstep, testing::ValuesIn(scene_names()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace tr
