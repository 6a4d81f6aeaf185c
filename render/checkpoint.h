// Checkpoints of a render in progress (`twinray render --checkpoint/--resume`): the FilmState
// and what it belongs to. A checkpoint is written atomically (io/temp_file.h), so a crash while
// writing leaves the previous one intact. Format (native byte order, read back by the same
// build only): the line "twinray checkpoint 2", one "key value" line per identity field and
// for the sample count, the line "end", then per pixel the 25 doubles of its FilmMoments
// (positive n, mean[3], m2[3], then negative, then the pass values' n, mean[3], m2[3] and the
// pass in progress's signs and sum[3]), the same for each FilmState::aovs entry, and the
// statistics (seconds as a double, samples, rays, rejected as uint64). Version 1 (without the
// passes) is refused.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "render/film_state.h"

namespace tr {

// A checkpoint that cannot be resumed; what() is one line "path: why".
struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What a checkpoint must match to be resumed.
struct RenderIdentity {
  std::string build;    // build_id()
  std::string scene;    // scenes/scene_digest.h of the loaded scene
  std::string backend;  // "cpu" or "gpu"
  std::uint32_t seed = 0;
  std::uint32_t granularity = 1;  // Renderer::granularity()
  std::uint32_t width = 0, height = 0;
  std::uint32_t aov_count = 0;  // Mitsuba `aov` output variables (FilmState::aov_count)
  std::uint32_t pass_size = 0;  // Renderer::pass_size() (FilmState::pass_size)
};

// This executable's GNU build ID (the linker's hash of its contents, .note.gnu.build-id) in hex.
std::string build_id();

// Throws FileError (io/temp_file.h) when it cannot write.
void write_checkpoint(const std::string& path, const RenderIdentity& id, const FilmState& film);
// Throws CheckpointError naming the first field that differs from `expected`, or the damage.
FilmState read_checkpoint(const std::string& path, const RenderIdentity& expected);

}  // namespace tr
