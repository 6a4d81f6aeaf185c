#include "validation/harness/scene_render.h"

#include "io/image.h"
#include "scenes/load_scene.h"

namespace tr {
namespace {

RgbImage as_image(const RenderResult& r, const std::vector<double>& values) {
  RgbImage img;
  img.width = int(r.width);
  img.height = int(r.height);
  img.rgb = values;
  if (img.rgb.size() != img.pixel_count() * 3)
    throw std::runtime_error("render result has " + std::to_string(img.rgb.size()) +
                             " values for " + std::to_string(img.pixel_count()) + " pixels");
  return img;
}

}  // namespace

Scene load_entry_scene(const SuiteEntry& entry) {
  LoadOptions options;
  options.defines = entry.defines;
  return load_scene(entry.scene, options);
}

std::uint32_t entry_spp(const SuiteEntry& entry, const Scene& scene) {
  if (entry.spp > 0) return entry.spp;
  const Camera& c = scene.buffers.globals.camera;
  return acceptance_spp(c.width, c.height);
}

std::uint32_t entry_seed(const SuiteEntry& entry, const Scene& scene) {
  return entry.seed.value_or(scene.seed);
}

SceneRender render_scene(const BackendRenderer& render, const std::string& backend,
                         const Scene& scene, std::uint32_t spp, std::uint32_t seed,
                         std::uint32_t threads) {
  RenderOptions options;
  options.spp = spp;
  options.seed = seed;
  options.threads = threads;
  SceneRender r;
  r.result = render(backend, scene, options);
  r.mean = mean_image(r.result);
  r.variance = variance_image(r.result);
  return r;
}

RgbImage mean_image(const RenderResult& r) { return as_image(r, r.mean); }

RgbImage variance_image(const RenderResult& r) { return as_image(r, r.variance); }

void write_preview_png(const std::string& path, const RgbImage& rgb) {
  Image img;
  img.width = rgb.width;
  img.height = rgb.height;
  img.channels = 3;
  img.pixels.assign(rgb.rgb.begin(), rgb.rgb.end());
  write_png_srgb(path, img);
}

}  // namespace tr
