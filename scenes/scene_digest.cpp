#include "scenes/scene_digest.h"

#include <cstdint>

#include "io/fnv1a.h"

namespace tr {

std::string scene_digest(const Scene& scene) {
  const SceneBuffers& b = scene.buffers;
  Fnv1a f;
  f.add(&b.globals, sizeof b.globals);
  f.add_vector(b.materials);
  f.add_vector(b.textures);
  f.add_vector(b.texels);
  f.add_vector(b.emitters);
  f.add_vector(b.alias);
  f.add_vector(b.light_nodes);
  f.add_vector(b.shapes);
  f.add_vector(b.instances);
  f.add_vector(b.positions);
  f.add_vector(b.normals);
  f.add_vector(b.uvs);
  f.add_vector(b.indices);
  f.add_vector(b.attributes);
  const std::uint8_t robust = scene.robust_intersections ? 1u : 0u;
  f.add(&robust, sizeof robust);
  return f.hex();
}

}  // namespace tr
