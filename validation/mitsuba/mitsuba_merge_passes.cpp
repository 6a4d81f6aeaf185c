// Merges the passes of a Mitsuba 3 reference (validation/mitsuba/moment_merge.h) into
// OUT_PREFIX.exr (mean, linear sRGB float32) and OUT_PREFIX_var.exr (per-sample variance).
// usage: mitsuba_merge_passes OUT_PREFIX [--meta key=value]... PASS.exr...
// Each --meta becomes a string attribute of both files, after the first pass's attributes.
// Exit status: 0 written, 2 bad arguments or unreadable/inconsistent passes.
#include <cstdio>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/image.h"
#include "validation/mitsuba/moment_merge.h"

int main(int argc, char** argv) {
  const char* usage = "usage: mitsuba_merge_passes OUT_PREFIX [--meta key=value]... PASS.exr...\n";
  try {
    std::string prefix;
    std::vector<std::pair<std::string, std::string>> meta;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--meta") {
        if (i + 1 >= argc) throw std::invalid_argument("--meta needs key=value");
        const std::string kv = argv[++i];
        const size_t eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
          throw std::invalid_argument("--meta expects key=value, got '" + kv + "'");
        meta.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
      } else if (prefix.empty()) {
        prefix = arg;
      } else {
        files.push_back(arg);
      }
    }
    if (prefix.empty() || files.empty())
      throw std::invalid_argument("OUT_PREFIX and at least one pass are required");

    std::vector<tr::Image> passes;
    for (const std::string& f : files) passes.push_back(tr::read_image(f));
    tr::MergedPasses merged = tr::merge_moment_passes(passes, files);

    std::map<std::string, std::string> attributes = passes.front().metadata;
    for (const auto& [key, value] : meta) attributes[key] = value;
    merged.mean.metadata = merged.variance.metadata = attributes;
    tr::write_exr(prefix + ".exr", merged.mean);
    tr::write_exr(prefix + "_var.exr", merged.variance);
    std::printf("merged %zu passes of %dx%d into %s.exr and %s_var.exr", passes.size(),
                merged.mean.width, merged.mean.height, prefix.c_str(), prefix.c_str());
    if (merged.clamped_variances > 0)
      std::printf("; %zu XYZ or AOV variances below 0 (down to %.3g) set to 0",
                  merged.clamped_variances, merged.most_negative_variance);
    std::printf("\n");
    return 0;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "mitsuba_merge_passes: %s\n%s", e.what(), usage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mitsuba_merge_passes: %s\n", e.what());
    return 2;
  }
}
