// Backend-neutral rendering interface: what a backend is asked for and what it returns.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tr {

struct Scene;

// The requested backend or device cannot render here; what() says what is missing.
struct BackendUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Called with (samples done, samples total) as the render progresses; may be empty.
using ProgressFn = std::function<void(std::uint64_t, std::uint64_t)>;

struct RenderOptions {
  std::uint32_t spp = 0;  // samples per pixel (0: the scene's sampler sample_count)
  std::uint32_t seed = 0;
  std::uint32_t threads = 0;  // CPU worker threads (0: all cores)
  std::string device;         // GPU device index or name substring ("" = first usable)
  ProgressFn progress;
};

struct RenderStats {
  double seconds = 0.0;
  std::uint64_t samples = 0;             // camera paths traced
  std::uint64_t rays = 0;                // closest-hit + shadow rays
  std::uint64_t rejected_nonfinite = 0;  // samples whose radiance was NaN/Inf, counted as 0
};

// Per pixel, per channel (RGB, row-major, top row first): the pixel's value and the per-sample
// variance of its estimate, accumulated in double (render/film_moments.h). For the box filter
// and filters without negative lobes these are the sample mean and the unbiased per-sample
// variance (Mitsuba `moment` semantics); with negative lobes, the ratio estimate and its
// delta-method variance. With a correlated sampler rendered in 2 or more passes the variance
// is instead S times the variance of the pass values (render/error_estimate.h): in every case
// variance / spp estimates the variance of the pixel's value.
struct RenderResult {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t spp = 0;
  std::uint32_t seed = 0;
  std::uint32_t pass_size = 0;  // FilmState::pass_size: samples of a pass, 0 without passes
  std::vector<double> mean;
  std::vector<double> variance;
  // Mitsuba `aov`: per pixel, 3 values for each of aov_count output variables (value and
  // per-sample variance as above; render/film_state.h develop_aovs).
  std::uint32_t aov_count = 0;
  std::vector<double> aov_mean;
  std::vector<double> aov_variance;
  RenderStats stats;
  std::string backend;  // "cpu" or "gpu"
  std::string device;   // e.g. "Embree 3.13.5, 2 threads" or the Vulkan device name
};

}  // namespace tr
