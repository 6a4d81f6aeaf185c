// Writes a render's outputs: OUT.exr (mean, RGB, with metadata), OUT_var.exr (the
// per-sample variance, Mitsuba `moment` semantics, same naming as Mitsuba's test
// references; for a correlated sampler's passes, render/error_estimate.h's estimate, named by
// the attribute twinray:variance_estimate) and OUT.png (sRGB preview). Each file is written
// atomically: a reader sees the old file or the complete new one, never a partial one.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "render/film_state.h"
#include "render/render.h"

namespace tr {

struct OutputPaths {
  std::string image;     // OUT.exr
  std::string variance;  // OUT_var.exr
  std::string preview;   // OUT.png
};

OutputPaths output_paths(const std::string& exr_path);

// Metadata written as EXR attributes: spp, seed, backend, device, time, version, the variance
// estimate (render/error_estimate.h variance_estimate_name), plus `extra`.
// `half`: both EXRs in 16-bit floats (the film's component_format float16), else 32-bit.
// `aov_channels` (Scene::aov_channels): the names of the AOV channels both EXRs carry after
// R, G, B, each variable's first channels of RenderResult::aov_mean/aov_variance.
void write_result(const RenderResult& result, const OutputPaths& paths,
                  const std::map<std::string, std::string>& extra, bool half,
                  const std::vector<std::vector<std::string>>& aov_channels = {});

// The same files developed from `film` one image at a time, without a RenderResult's images in
// double: `header` is film_result_header's (render/renderer.h). The values written are
// write_result's of film_result(film), bit for bit.
void write_film(const FilmState& film, const RenderResult& header, const OutputPaths& paths,
                const std::map<std::string, std::string>& extra, bool half,
                const std::vector<std::vector<std::string>>& aov_channels = {});

}  // namespace tr
