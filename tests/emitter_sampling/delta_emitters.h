// Scenes of one delta emitter for the closed-form emitter tests (spot, projector).
#ifndef TWINRAY_TESTS_EMITTER_SAMPLING_DELTA_EMITTERS_H
#define TWINRAY_TESTS_EMITTER_SAMPLING_DELTA_EMITTERS_H

#include <string>

#include "core/emitter.h"
#include "scenes/load_scene.h"

namespace tr {

// A scene holding `body` and a default sensor, written to a temporary folder and loaded.
Scene load_emitter_scene(const std::string& name, const std::string& body);

// The scene's one emitter sampled from p (the emitter choice draws from an rng; with one
// emitter it is certain).
EmitterSample sample_towards(vec3 p);

// Writes a width x height float EXR whose texel (i, j), row 0 at the top, holds (i, j, 1), so
// that a nearest-filtered lookup says which texel it read; returns its path.
std::string write_texel_positions(const std::string& name, int width, int height);

}  // namespace tr

#endif
