// Render variants of `twinray converge`: integrator settings patched into a loaded scene
// (SceneGlobals::integrator, read by both backends), its sampler, and the backend to render
// with.
//
// A variant is written as comma-separated KEY=VALUE fields:
//   integrator=path|direct   Mitsuba's `path` or `direct` (emitter and BSDF samples 1 each)
//   max_depth=N              -1 for unbounded (Mitsuba semantics: 2 = direct lighting only)
//   rr_depth=N|off           depth at which Russian roulette starts; off never starts it
//   sampler=NAME             the scene's sampler replaced by NAME (scenes/sampler.h), jitter on
//   emitter_selection=uniform|power|bvh  how light samples choose an emitter
//                            (scenes/emitter_selection.h; the scene is loaded with Mitsuba's)
//   randomizations=K         each render's samples as K passes of the (correlated) sampler,
//                            whose spread is its error estimate (render/error_estimate.h)
//   backend=cpu|gpu
//   label=TEXT               the series name (default: the fields as given, or "scene")
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "scenes/scene.h"

namespace tr {

struct VariantError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct RenderVariant {
  std::string label;
  std::string backend = "cpu";
  std::optional<uint> integrator;  // INTEGRATOR_*
  std::optional<int> max_depth, rr_depth;
  std::optional<uint> sampler;            // SAMPLER_*
  std::optional<uint> randomizations;     // passes a render (scenes/sampler.h)
  std::optional<uint> emitter_selection;  // EMITTER_SELECTION_*
};

// Throws VariantError naming the bad field.
RenderVariant parse_variant(const std::string& spec);

// The scene with the variant's integrator settings and sampler.
Scene apply_variant(const Scene& scene, const RenderVariant& variant);

// The variant's scene at `spp` samples per pixel (in its randomizations); throws SceneError.
void set_variant_sample_count(Scene& scene, const RenderVariant& variant, uint spp);

}  // namespace tr
