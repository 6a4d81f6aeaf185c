// False-colour visualisation of a scalar field (an error map) as an 8-bit PNG.
#pragma once

#include <string>
#include <vector>

#include "io/colormap.h"

namespace tr {

// values: width*height scalars, row-major, top row first. Each value v is shown as the
// colormap at (v - lo) / (hi - lo), clamped; NaN is shown as the colormap's low end.
// Written atomically like write_png_srgb; throws ImageError.
void write_heatmap_png(const std::string& path, int width, int height,
                       const std::vector<float>& values, float lo, float hi,
                       Colormap map = Colormap::magma);

}  // namespace tr
