// Perceptually uniform colormaps (van der Walt & Smith, matplotlib's viridis/magma, 2015),
// evaluated through Matt Zucker's degree-6 minimax polynomial fits of the BIDS/colormap data
// (https://www.shadertoy.com/view/WlfXRN, CC0); they deviate from the tables by up to ~0.02.
#pragma once

#include <array>

namespace tr {

enum class Colormap { magma, viridis };

// The colour at t (clamped to [0, 1]) as sRGB-encoded values in [0, 1].
std::array<float, 3> colormap_srgb(Colormap map, float t);

}  // namespace tr
