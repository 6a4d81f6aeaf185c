#include "app/render_passes.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "render/film_error.h"

namespace tr {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Passes aim at this long: short enough to stop, save or report soon, long enough that the
// error estimate and the progress bar cost nothing.
constexpr double kPassSeconds = 1.0;

}  // namespace

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::Spp:
      return "spp";
    case StopReason::Time:
      return "time";
    case StopReason::Error:
      return "error";
    case StopReason::Interrupted:
      return "interrupted";
  }
  return "spp";
}

PassOutcome render_passes(Renderer& renderer, FilmState& film, const RenderBudget& budget,
                          double checkpoint_seconds,
                          const std::function<void(const FilmState&)>& save,
                          const ProgressFn& progress, const std::function<bool()>& stop_requested) {
  const Clock::time_point start = Clock::now();
  Clock::time_point last_save = start;
  const std::uint32_t g = std::max(renderer.granularity(), 1u);
  const std::uint32_t first = film.samples;
  const std::uint64_t pixels = std::uint64_t(film.width) * film.height;
  const std::uint64_t total = std::uint64_t(budget.spp - first) * pixels;
  double rate = 0.0;  // samples per pixel per second, measured
  PassOutcome outcome;
  outcome.error = estimated_relative_error(film);
  for (;;) {
    if (film.samples >= budget.spp) {
      outcome.stop = StopReason::Spp;
      break;
    }
    if (budget.error > 0.0 && outcome.error <= budget.error) {
      outcome.stop = StopReason::Error;
      break;
    }
    if (stop_requested && stop_requested()) {
      outcome.stop = StopReason::Interrupted;
      break;
    }
    double seconds = kPassSeconds;
    if (budget.seconds > 0.0) {
      const double left = budget.seconds - seconds_since(start);
      // Stop when not even one granule fits in the time left.
      if (left <= 0.0 || (rate > 0.0 && double(g) / rate > left)) {
        outcome.stop = StopReason::Time;
        break;
      }
      seconds = std::min(seconds, left);
    }
    std::uint32_t count = g;
    if (rate > 0.0) {
      const double want = std::floor(rate * seconds / double(g)) * double(g);
      count = std::uint32_t(std::clamp(want, double(g), double(budget.spp)));
    }
    if (budget.error > 0.0 && std::isfinite(outcome.error)) {
      // The error falls as 1 / sqrt(n): do not pass the sample count that should reach it.
      const double needed =
          double(film.samples) * (outcome.error / budget.error) * (outcome.error / budget.error);
      const double more = std::ceil((needed - double(film.samples)) / double(g)) * double(g);
      count = std::uint32_t(std::clamp(more, double(g), double(count)));
    }
    count = std::min(count, budget.spp - film.samples);
    const std::uint64_t before = std::uint64_t(film.samples - first) * pixels;
    const Clock::time_point pass_start = Clock::now();
    renderer.render(count, film, [&](std::uint64_t done, std::uint64_t) {
      if (progress) progress(before + done, total);
    });
    rate = double(count) / std::max(seconds_since(pass_start), 1e-6);
    outcome.error = estimated_relative_error(film);
    if (checkpoint_seconds > 0.0 && seconds_since(last_save) >= checkpoint_seconds) {
      save(film);
      last_save = Clock::now();
    }
  }
  if (checkpoint_seconds > 0.0) save(film);
  return outcome;
}

}  // namespace tr
