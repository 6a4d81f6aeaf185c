#include "io/heatmap.h"

#include "io/image.h"
#include "io/srgb.h"

namespace tr {

void write_heatmap_png(const std::string& path, int width, int height,
                       const std::vector<float>& values, float lo, float hi, Colormap map) {
  if (width <= 0 || height <= 0 || values.size() != size_t(width) * height)
    throw ImageError(path + ": heatmap needs width*height values, got " +
                     std::to_string(values.size()) + " for " + std::to_string(width) + "x" +
                     std::to_string(height));
  if (!(hi > lo))
    throw ImageError(path + ": heatmap range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "] is empty");
  Image img;
  img.width = width;
  img.height = height;
  img.channels = 3;
  img.pixels.resize(values.size() * 3);
  for (size_t i = 0; i < values.size(); ++i) {
    std::array<float, 3> rgb = colormap_srgb(map, (values[i] - lo) / (hi - lo));
    // write_png_srgb encodes linear values; the colormap is defined in sRGB, so decode it.
    for (int c = 0; c < 3; ++c) img.pixels[3 * i + c] = srgb_decode(rgb[c]);
  }
  img.metadata["twinray:heatmap_range"] = std::to_string(lo) + " " + std::to_string(hi);
  img.metadata["twinray:colormap"] = map == Colormap::magma ? "magma" : "viridis";
  write_png_srgb(path, img);
}

}  // namespace tr
