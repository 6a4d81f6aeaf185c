// Building the light BVH of core/light_bvh.h (pbrt-v4 §12.6.3, BVHLightSampler::buildBVH): top
// down, each node split where the surface area orientation heuristic (Conty Estevez & Kulla
// 2018, eq. 1-2) is least over 12 buckets of the emitters' centres along each axis.
#pragma once

#include <vector>

#include "scenes/light_bounds.h"

namespace tr {

// Fills `nodes` (one leaf per entry of `bounds`, then the interior nodes) over the emitters
// listed in `members` (their power taken from `phi`) and returns the root, or NO_INDEX when
// `members` is empty.
uint build_light_bvh(const std::vector<LightBounds>& bounds, const std::vector<double>& phi,
                     std::vector<uint> members, std::vector<LightNode>& nodes);

}  // namespace tr
