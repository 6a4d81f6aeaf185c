// A glTF 2.0 file's accessors decoded (spec "Accessors": component types, normalized integers,
// byte strides, sparse substitution) and its mesh primitives assembled from them by the file's
// own indices (spec "Meshes": triangles, strips and fans), never by a library's internal order.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "scenes/assimp/imported_geometry.h"
#include "scenes/gltf/gltf_buffers.h"

namespace tr {

class GltfAccessors {
 public:
  GltfAccessors(const nlohmann::json& doc, GltfBuffers& buffers) : doc_(doc), buffers_(buffers) {}

  // accessors[a] as floats, `components` per element (1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4);
  // normalized integers map to [0, 1] or [-1, 1] (spec "Animation"/"Accessors": c / (2^n - 1),
  // max(c / (2^(n-1) - 1), -1)). Throws GltfFieldError.
  std::vector<float> floats(size_t a, int components);

  // accessors[a] as vertex indices (SCALAR, unsigned byte, short or int, not normalized).
  std::vector<std::uint32_t> indices(size_t a);

  // meshes[m].primitives[k], whose mode is triangles, strip or fan: its positions, normals and
  // TEXCOORD_0 (glTF's v, origin at the image's top-left, as read), its tangent frames from
  // TANGENT where it has NORMAL too (scenes/gltf/gltf_tangents.h), and its triangles.
  ImportedMesh primitive(size_t m, size_t k);

 private:
  struct Layout {
    int component_type = 0;
    int components = 0;
    bool normalized = false;
    size_t count = 0;
  };
  Layout layout(size_t a);
  std::vector<double> decode(size_t a, const Layout& l);

  const nlohmann::json& doc_;
  GltfBuffers& buffers_;
};

}  // namespace tr
