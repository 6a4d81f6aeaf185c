// CPU <-> GPU lockstep on the default scene (issue 4): the Cornell box (96x96) at 1 and 64 spp.
#include <gtest/gtest.h>

#include "lockstep_check.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

Scene cornell_box() {
  LoadOptions load;
  load.defines["width"] = "96";
  load.defines["height"] = "96";
  return load_scene(TWINRAY_CORNELL_BOX, load);
}

TEST(CornellLockstep, OneSamplePerPixel) { expect_lockstep("Cornell box", cornell_box(), 1, 21); }
TEST(CornellLockstep, SixtyFourSamplesPerPixel) {
  expect_lockstep("Cornell box", cornell_box(), 64, 22);
}

}  // namespace
}  // namespace tr
