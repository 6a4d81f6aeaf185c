// Rendering a suite entry with a backend, and the render as images the comparisons take.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "render/render.h"
#include "scenes/scene.h"
#include "validation/harness/suite.h"
#include "validation/image/rgb_image.h"

namespace tr {

struct SceneRender {
  RenderResult result;
  // variance: RenderResult::variance, per sample (Mitsuba `moment` semantics) or, for a
  // correlated sampler in 2 or more passes, their estimate (render/error_estimate.h); divided
  // by spp it estimates the variance of the pixel's value either way.
  RgbImage mean, variance;
};

// load_scene with the entry's defines; throws SceneError.
Scene load_entry_scene(const SuiteEntry& entry);

// The entry's spp, or acceptance_spp of the scene's film when the entry says auto.
std::uint32_t entry_spp(const SuiteEntry& entry, const Scene& scene);
// The entry's seed, or the scene's sampler seed.
std::uint32_t entry_seed(const SuiteEntry& entry, const Scene& scene);

// Renders a scene with the backend named "cpu" or "gpu"; throws BackendUnavailable when it
// cannot. The command line supplies it (app/run_backend.h), so validation/ knows no backend.
using BackendRenderer =
    std::function<RenderResult(const std::string& backend, const Scene&, const RenderOptions&)>;

// `render` with spp, seed and threads (0: all cores); throws BackendUnavailable.
SceneRender render_scene(const BackendRenderer& render, const std::string& backend,
                         const Scene& scene, std::uint32_t spp, std::uint32_t seed,
                         std::uint32_t threads = 0);

RgbImage mean_image(const RenderResult& r);
RgbImage variance_image(const RenderResult& r);

// 8-bit sRGB preview (io/image.h write_png_srgb); throws ImageError.
void write_preview_png(const std::string& path, const RgbImage& img);

}  // namespace tr
