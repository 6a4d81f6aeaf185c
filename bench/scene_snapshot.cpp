#include "bench/scene_snapshot.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace tr {
namespace {

constexpr char kMagic[8] = {'T', 'W', 'S', 'C', 'E', 'N', 'E', '1'};

template <typename T>
void put(std::ofstream& out, const std::vector<T>& v) {
  std::uint64_t n = v.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(n * sizeof(T)));
}

void put(std::ofstream& out, const std::string& s) { put(out, std::vector<char>(s.begin(), s.end())); }

template <typename T>
void get(std::ifstream& in, std::vector<T>& v) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  if (!in || n > (std::uint64_t(1) << 36) / sizeof(T)) throw std::runtime_error("corrupt scene snapshot");
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)));
}

void get(std::ifstream& in, std::string& s) {
  std::vector<char> c;
  get(in, c);
  s.assign(c.begin(), c.end());
}

}  // namespace

void write_scene_snapshot(const std::string& path, const Scene& scene) {
  std::ofstream out(path, std::ios::binary);
  const SceneBuffers& b = scene.buffers;
  out.write(kMagic, sizeof kMagic);
  out.write(reinterpret_cast<const char*>(&b.globals), sizeof b.globals);
  put(out, b.materials);
  put(out, b.textures);
  put(out, b.texels);
  put(out, b.emitters);
  put(out, b.alias);
  put(out, b.shapes);
  put(out, b.instances);
  put(out, b.positions);
  put(out, b.normals);
  put(out, b.uvs);
  put(out, b.indices);
  put(out, scene.path);
  put(out, scene.integrator_name);
  out.write(reinterpret_cast<const char*>(&scene.spp), sizeof scene.spp);
  out.write(reinterpret_cast<const char*>(&scene.seed), sizeof scene.seed);
  if (!out) throw std::runtime_error(path + ": cannot write the scene snapshot");
}

Scene read_scene_snapshot(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8];
  in.read(magic, sizeof magic);
  if (!in || std::memcmp(magic, kMagic, sizeof magic) != 0) throw std::runtime_error(path + ": not a scene snapshot");
  Scene scene;
  SceneBuffers& b = scene.buffers;
  in.read(reinterpret_cast<char*>(&b.globals), sizeof b.globals);
  get(in, b.materials);
  get(in, b.textures);
  get(in, b.texels);
  get(in, b.emitters);
  get(in, b.alias);
  get(in, b.shapes);
  get(in, b.instances);
  get(in, b.positions);
  get(in, b.normals);
  get(in, b.uvs);
  get(in, b.indices);
  get(in, scene.path);
  get(in, scene.integrator_name);
  in.read(reinterpret_cast<char*>(&scene.spp), sizeof scene.spp);
  in.read(reinterpret_cast<char*>(&scene.seed), sizeof scene.seed);
  if (!in) throw std::runtime_error(path + ": truncated scene snapshot");
  return scene;
}

}  // namespace tr
