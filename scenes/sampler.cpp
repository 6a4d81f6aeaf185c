#include "scenes/sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace tr {

namespace {

const std::uint64_t MAX_PASS = 1u << 24;  // pass indices stay exact in float (core/samplers/)

// Mitsuba's plugin names, by SAMPLER_*.
const std::array<const char*, 7> SAMPLER_NAMES = {
    "independent", "stratified", "ldsampler", "multijitter", "orthogonal", "zsobol", "sobol"};

std::uint64_t smallest_prime_at_least(std::uint64_t x) {
  for (;; ++x) {
    bool prime = true;
    for (std::uint64_t d = 2; d * d <= x && prime; ++d) prime = x % d != 0;
    if (prime) return x;
  }
}

}  // namespace

bool sampler_type_of(const std::string& name, uint& type) {
  for (uint t = 0; t < SAMPLER_NAMES.size(); ++t)
    if (name == SAMPLER_NAMES[t]) {
      type = t;
      return true;
    }
  return false;
}

const char* sampler_name(uint type) { return SAMPLER_NAMES.at(type); }

uint rounded_sample_count(uint type, uint requested) {
  std::uint64_t n = requested;
  if (type == SAMPLER_STRATIFIED) {
    std::uint64_t r = 1;
    while (r * r < n) ++r;
    n = r * r;
  } else if (type == SAMPLER_LDSAMPLER) {
    std::uint64_t r = 2;
    while (r * r < n) r *= 2;
    n = r * r;
  } else if (type == SAMPLER_ORTHOGONAL) {
    std::uint64_t p = smallest_prime_at_least(2);
    while (p * p < n) p = smallest_prime_at_least(p + 1);
    n = p * p;
  } else if (type == SAMPLER_ZSOBOL || type == SAMPLER_SOBOL) {
    std::uint64_t r = 1;
    while (r < n) r *= 2;
    n = r;
  } else if (type == SAMPLER_MULTIJITTER) {
    std::uint64_t rows = std::uint64_t(std::sqrt(float(requested)));  // as Mitsuba, in float
    n = (n + rows - 1) / rows * rows;
  }
  if (type != SAMPLER_INDEPENDENT && n > MAX_PASS)
    throw SceneError(std::string(sampler_name(type)) + ": sample_count " +
                     std::to_string(requested) + " exceeds 2^24");
  return uint(n);
}

void set_sampler(Scene& scene, uint type, uint requested, bool jitter) {
  uint n = rounded_sample_count(type, requested);
  Sampler& s = scene.buffers.globals.sampler_params;
  s.type = type;
  // independent has no passes: its record stays the same whatever the count, so that a
  // checkpoint resumes under another --spp (the scene digest covers the record).
  s.sample_count = type == SAMPLER_INDEPENDENT ? 1u : n;
  s.jitter = jitter ? 1u : 0u;
  s.resolution = uvec2(1u);
  if (type == SAMPLER_STRATIFIED || type == SAMPLER_ORTHOGONAL) {
    uint r = uint(std::lround(std::sqrt(double(n))));
    s.resolution = uvec2(r);
  } else if (type == SAMPLER_MULTIJITTER) {
    uint rows = uint(std::sqrt(float(requested)));
    s.resolution = uvec2(n / rows, rows);
  } else if (type == SAMPLER_ZSOBOL) {
    // pbrt-v4: log2 of the film's larger side rounded up to a power of 2, plus ceil(log4 n).
    const Camera& c = scene.buffers.globals.camera;
    if (std::max(c.width, c.height) > 65536u)  // Morton codes of 16-bit coordinates
      throw SceneError("zsobol: a film of more than 65536 pixels a side");
    uint log2_side = 0, log2_n = 0;
    while ((1u << log2_side) < std::max(c.width, c.height)) ++log2_side;
    while ((1u << log2_n) < n) ++log2_n;
    s.resolution = uvec2(c.width, log2_side + (log2_n + 1) / 2);
  }
  s.inv_sample_count = 1.0f / float(s.sample_count);
  s.inv_resolution = vec2(1.0f) / vec2(s.resolution);
  scene.spp = n;
  scene.sample_count_note.clear();
  if (n != requested)
    scene.sample_count_note =
        std::string(sampler_name(type)) + ": sample_count " + std::to_string(requested) +
        " rounded up to " + std::to_string(n) +
        (type == SAMPLER_ZSOBOL || type == SAMPLER_SOBOL ? ", as pbrt-v4" : ", as Mitsuba");
}

void set_sample_count(Scene& scene, uint requested) {
  const Sampler& s = scene.buffers.globals.sampler_params;
  set_sampler(scene, s.type, requested, s.jitter != 0u);
}

void set_sample_count_in_passes(Scene& scene, uint requested, uint passes) {
  const Sampler& s = scene.buffers.globals.sampler_params;
  if (s.type == SAMPLER_INDEPENDENT) return set_sample_count(scene, requested);
  set_sampler(scene, s.type, requested / passes + (requested % passes != 0 ? 1u : 0u),
              s.jitter != 0u);
  const std::uint64_t total = std::uint64_t(passes) * s.sample_count;
  if (total > 0xffffffffu)
    throw SceneError(std::to_string(passes) + " passes of " + std::to_string(s.sample_count) +
                     " samples: " + std::to_string(total) + " samples per pixel are too many");
  scene.spp = uint(total);
}

}  // namespace tr
