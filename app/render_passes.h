// Progressive rendering: a render as passes over consecutive sample ranges, stopped by the
// first budget reached (samples, time, estimated error) or by a stop request, with periodic
// checkpoints. Pass boundaries fall on the renderer's granularity, so the image is the one an
// uninterrupted render of the same sample count gives, bit for bit (render/renderer.h).
#pragma once

#include <cstdint>
#include <functional>

#include "render/renderer.h"

namespace tr {

struct RenderBudget {
  std::uint32_t spp = 0;  // the cap: samples per pixel in all
  double seconds = 0.0;   // rendering time of this run; 0: none
  double error = 0.0;     // render/film_error.h estimate to reach; 0: none
};

enum class StopReason { Spp, Time, Error, Interrupted };
const char* stop_reason_name(StopReason r);  // "spp", "time", "error", "interrupted"

struct PassOutcome {
  StopReason stop = StopReason::Spp;
  double error = 0.0;  // the estimate reached
};

// Renders passes into `film` until a budget is reached or stop_requested() says so (checked
// between passes: the pass in flight is finished). With checkpoint_seconds > 0, calls
// save(film) whenever that much time has passed since the last save, and once at the end.
PassOutcome render_passes(Renderer& renderer, FilmState& film, const RenderBudget& budget,
                          double checkpoint_seconds,
                          const std::function<void(const FilmState&)>& save,
                          const ProgressFn& progress, const std::function<bool()>& stop_requested);

}  // namespace tr
