// The pass size a backend gives its FilmState (render/film_state.h): the scene's sampler's
// sample_count for the samplers whose samples come in correlated passes (core/rng.h), 0 for
// `independent`, whose samples are independent and have no passes.
#pragma once

#include <cstdint>

#include "core/scene_types.h"

namespace tr {

inline std::uint32_t sampler_pass_size(const Sampler& sampler) {
  return sampler.type == SAMPLER_INDEPENDENT ? 0u : sampler.sample_count;
}

}  // namespace tr
