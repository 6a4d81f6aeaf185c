// One lockstep check (issue 4): `scene` rendered on the CPU and the GPU with the same spp and
// seed; at least 99% of the pixels agree within 1e-4 relative (+1e-6 absolute) and no 4x4
// window shows a systematic or clustered difference (validation/image/lockstep.h), the cluster
// check leaving out the pixels that a CPU render with the camera moved by one ulp shows to be
// rounding-sensitive. The fraction and the worst pixels are printed with their coordinates.
#pragma once

#include <cstdint>
#include <string>

#include "scenes/scene.h"
#include "validation/image/lockstep.h"

namespace tr {

void expect_lockstep(const std::string& label, const Scene& scene, uint32_t spp, uint32_t seed,
                     const LockstepOptions& options = {});

}  // namespace tr
