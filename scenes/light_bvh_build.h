// Building the light BVH of core/light_bvh.h (pbrt-v4 §12.6.3, BVHLightSampler::buildBVH): top
// down, each node split where the surface area orientation heuristic (Conty Estevez & Kulla
// 2018, eq. 1-2) is least over 12 buckets of the emitters' centres along each axis; the binary
// tree is then collapsed to up to LIGHT_BVH_WIDTH children a node.
#pragma once

#include <vector>

#include "scenes/light_bounds.h"

namespace tr {

// Fills `nodes` with the tree over the emitters listed in `members` (entries of `bounds`, their
// power taken from `phi`), laid out as core/scene_types.h's LightNode describes, and `leaves`
// with each entry's leaf (NO_INDEX for those not in `members`); returns the root (0), or
// NO_INDEX when `members` is empty.
uint build_light_bvh(const std::vector<LightBounds>& bounds, const std::vector<double>& phi,
                     std::vector<uint> members, std::vector<LightNode>& nodes,
                     std::vector<uint>& leaves);

}  // namespace tr
