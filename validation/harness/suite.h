// Suite files of `twinray validate`: the scenes to render and the references to judge them by.
//
// Format: plain text, one scene per line, whitespace-separated KEY=VALUE fields; blank lines
// and lines starting with '#' are ignored. Relative paths are relative to the suite file.
//   name=NAME            unique label (letters, digits, '_', '-'), used in file names
//   scene=PATH           Mitsuba 3 XML scene
//   reference=PATH       reference image (mean radiance, linear RGB)
//   variance=PATH        per-sample variance of the reference (default: reference's
//                        stem + "_var" + extension, the naming of Mitsuba's test references)
//   reference_spp=N      samples per pixel of the reference
//   spp=N|auto           samples per pixel to render; auto = floor(2e6 / (width * height)),
//                        the sample budget of shared/mitsuba-tests/README.md (default auto)
//   seed=N               sampler seed (default: the scene's sampler `seed`)
//   lockstep_spp=N       compare the CPU and GPU backends on renders of N spp of their own
//                        (default: the renders judged against the reference). Lockstep asks
//                        every sample of a pixel to follow the same path on both; a scene whose
//                        paths branch on textured values (a blend weight, a normal map's
//                        horizon) diverges by float rounding in a few samples per 10^5, so at
//                        hundreds of spp more than 1% of its pixels hold one such sample.
//   define=NAME=VALUE    a scene <default> override (like render -D); may repeat
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tr {

// A malformed suite file; what() is "file:line: what and why".
struct SuiteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SuiteEntry {
  std::string name;
  std::string scene, reference, variance;  // resolved paths
  double reference_spp = 0.0;
  std::uint32_t spp = 0;              // 0: auto
  std::optional<std::uint32_t> seed;  // unset: the scene's sampler seed
  std::uint32_t lockstep_spp = 0;     // 0: the spp of the reference comparison
  std::map<std::string, std::string> defines;
};

std::vector<SuiteEntry> read_suite(const std::string& path);

// The entry named `name`; throws SuiteError when there is none.
const SuiteEntry& find_entry(const std::vector<SuiteEntry>& suite, const std::string& name);

// shared/mitsuba-tests/README.md: spp = floor(2e6 / (width * height)).
std::uint32_t acceptance_spp(std::uint32_t width, std::uint32_t height);

}  // namespace tr
