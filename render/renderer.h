// A backend bound to one scene, rendering consecutive sample ranges into a FilmState: the unit
// of progressive rendering (passes, time and error budgets, checkpoints; app/render_command).
#pragma once

#include <cstdint>
#include <string>

#include "render/film_state.h"
#include "render/render.h"

namespace tr {

class Renderer {
 public:
  virtual ~Renderer() = default;

  // Adds samples [film.samples, film.samples + count) of every pixel to `film` and advances
  // film.samples; progress (may be empty) gets (samples done, samples total) of this range.
  virtual void render(std::uint32_t count, FilmState& film, const ProgressFn& progress) = 0;

  // Passes that end on multiples of this many samples per pixel (or at the render's last
  // sample) give the image of one uninterrupted render, bit for bit.
  virtual std::uint32_t granularity() const = 0;

  // Samples of one pass of the scene's sampler (FilmState::pass_size), 0 without passes.
  virtual std::uint32_t pass_size() const = 0;

  virtual std::string backend() const = 0;  // "cpu" or "gpu"
  virtual std::string device() const = 0;   // e.g. "Embree 3.13.5, 2 threads"
  virtual std::uint32_t seed() const = 0;
};

// What `film` as rendered by `renderer` is, without its images (mean, variance and the AOVs'
// left empty).
inline RenderResult film_result_header(const FilmState& film, const Renderer& renderer) {
  RenderResult r;
  r.width = film.width;
  r.height = film.height;
  r.spp = film.samples;
  r.seed = renderer.seed();
  r.pass_size = film.pass_size;
  r.aov_count = film.aov_count;
  r.stats = film.stats;
  r.backend = renderer.backend();
  r.device = renderer.device();
  return r;
}

// The developed image of `film` as rendered by `renderer`.
inline RenderResult film_result(const FilmState& film, const Renderer& renderer) {
  RenderResult r = film_result_header(film, renderer);
  develop_film(film, r.mean, r.variance);
  develop_aovs(film, r.aov_mean, r.aov_variance);
  return r;
}

// Renders `spp` samples per pixel in one range.
inline RenderResult render_all(Renderer& renderer, std::uint32_t width, std::uint32_t height,
                               std::uint32_t spp, const ProgressFn& progress,
                               std::uint32_t aov_count = 0) {
  FilmState film = empty_film(width, height, aov_count, renderer.pass_size());
  renderer.render(spp, film, progress);
  return film_result(film, renderer);
}

}  // namespace tr
