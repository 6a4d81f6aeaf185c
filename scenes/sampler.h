// The scene's sampler on the host: Mitsuba 3.8's sample_count rounding (set_sample_count in
// src/samplers/*.cpp) and the device record of core/scene_types.h.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace tr {

// SAMPLER_* of a Mitsuba sampler type name; false when twinray has no such sampler.
bool sampler_type_of(const std::string& name, uint& type);
const char* sampler_name(uint type);

// The sample count Mitsuba renders when asked for `requested`: stratified the next square,
// ldsampler the next power of 4 (at least 4), multijitter floor(sqrt(n)) rows of
// ceil(n / rows) columns, orthogonal the square of the next prime (at least 4); zsobol and sobol
// (pbrt-v4) the next power of 2; independent keeps it. Throws SceneError past 2^24 points a pass.
uint rounded_sample_count(uint type, uint requested);

// Sets the scene's sampler to `type` at `requested` samples per pixel, rounded as Mitsuba
// (zsobol, sobol: pbrt-v4) rounds it; zsobol reads the film's size from globals.camera, which must
// be set: globals.sampler, Scene.spp and Scene.sample_count_note ("stratified: sample_count 10
// rounded up to 16, as Mitsuba", empty when not rounded).
void set_sampler(Scene& scene, uint type, uint requested, bool jitter);

// --spp N: the same rounding for the scene's sampler.
void set_sample_count(Scene& scene, uint requested);

// --randomizations K: `requested` samples per pixel as K passes (independent randomizations,
// render/error_estimate.h) of ceil(requested / K) samples, rounded as the sampler rounds
// sample_count; Scene.spp becomes K times the pass. independent, which has no passes, takes
// `requested` as it is. Throws SceneError past 2^32 - 1 samples.
void set_sample_count_in_passes(Scene& scene, uint requested, uint passes);

}  // namespace tr
