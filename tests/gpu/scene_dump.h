// Raw dump of a loaded scene's records (every vector of SceneBuffers, its globals, spp and seed),
// so that the GPU benchmark can run on machines without the loader's dependencies: the records are
// the std430 bytes the backend uploads, written vector by vector as (count, bytes).
#pragma once

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace tr::test {

template <typename T>
void dump_vector(std::ofstream& out, const std::vector<T>& v) {
  std::uint64_t n = v.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof(n));
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(n * sizeof(T)));
}

template <typename T>
void undump_vector(std::ifstream& in, std::vector<T>& v) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof(n));
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)));
}

inline void save_scene_dump(const Scene& s, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  const SceneBuffers& b = s.buffers;
  out.write(reinterpret_cast<const char*>(&b.globals), sizeof(b.globals));
  out.write(reinterpret_cast<const char*>(&s.spp), sizeof(s.spp));
  out.write(reinterpret_cast<const char*>(&s.seed), sizeof(s.seed));
  dump_vector(out, b.materials);
  dump_vector(out, b.textures);
  dump_vector(out, b.texels);
  dump_vector(out, b.emitters);
  dump_vector(out, b.alias);
  dump_vector(out, b.light_nodes);
  dump_vector(out, b.shapes);
  dump_vector(out, b.instances);
  dump_vector(out, b.positions);
  dump_vector(out, b.normals);
  dump_vector(out, b.uvs);
  dump_vector(out, b.indices);
  dump_vector(out, b.attributes);
  if (!out) throw std::runtime_error("cannot write " + path);
}

inline Scene load_scene_dump(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  Scene s;
  SceneBuffers& b = s.buffers;
  in.read(reinterpret_cast<char*>(&b.globals), sizeof(b.globals));
  in.read(reinterpret_cast<char*>(&s.spp), sizeof(s.spp));
  in.read(reinterpret_cast<char*>(&s.seed), sizeof(s.seed));
  undump_vector(in, b.materials);
  undump_vector(in, b.textures);
  undump_vector(in, b.texels);
  undump_vector(in, b.emitters);
  undump_vector(in, b.alias);
  undump_vector(in, b.light_nodes);
  undump_vector(in, b.shapes);
  undump_vector(in, b.instances);
  undump_vector(in, b.positions);
  undump_vector(in, b.normals);
  undump_vector(in, b.uvs);
  undump_vector(in, b.indices);
  undump_vector(in, b.attributes);
  if (!in) throw std::runtime_error(path + " is truncated");
  s.path = path;
  return s;
}

}  // namespace tr::test
