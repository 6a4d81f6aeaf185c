#include "delta_emitters.h"

#include <filesystem>
#include <fstream>
#include <vector>

#include "io/image.h"

namespace tr {
namespace {

std::filesystem::path test_dir() {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "twinray_delta_emitters";
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

Scene load_emitter_scene(const std::string& name, const std::string& body) {
  std::filesystem::path file = test_dir() / (name + ".xml");
  std::ofstream(file) << "<scene version=\"3.0.0\"><sensor type=\"perspective\"/>" << body
                      << "</scene>\n";
  return load_scene(file.string(), LoadOptions());
}

EmitterSample sample_towards(vec3 p) {
  Rng rng = rng_init(0u, 0u, 0u);
  return sample_emitter(p, rng);
}

std::string write_texel_positions(const std::string& name, int width, int height) {
  std::string path = (test_dir() / (name + ".exr")).string();
  Image texels;
  texels.width = width;
  texels.height = height;
  texels.channels = 3;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      texels.pixels.insert(texels.pixels.end(), {float(i), float(j), 1.0f});
  write_exr(path, texels);
  return path;
}

}  // namespace tr
