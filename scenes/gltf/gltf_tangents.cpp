#include "scenes/gltf/gltf_tangents.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <map>

#include "core/frame.h"

namespace tr {

namespace {

glm::dvec3 vec3_at(const std::vector<float>& v, std::uint32_t i) {
  return glm::dvec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
}

glm::dvec3 normalized_or_zero(const glm::dvec3& v) {
  double len = glm::length(v);
  return len > 0.0 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

// The bits of a corner's position, normal and uv, and its orientation: corners equal here
// share a tangent.
using CornerKey = std::array<std::uint32_t, 9>;

std::uint32_t bits(double v) {
  float f = float(v);
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

}  // namespace

void set_gltf_tangents(ImportedMesh& mesh, const std::vector<float>& tangent_xyzw) {
  const std::size_t vertices = mesh.positions.size() / 3;
  mesh.tangents.resize(3 * vertices);
  mesh.bitangents.resize(3 * vertices);
  for (std::size_t i = 0; i < vertices; ++i) {
    glm::dvec3 t(tangent_xyzw[4 * i], tangent_xyzw[4 * i + 1], tangent_xyzw[4 * i + 2]);
    double w = tangent_xyzw[4 * i + 3] < 0.0f ? -1.0 : 1.0;
    glm::dvec3 b = w * glm::cross(vec3_at(mesh.normals, std::uint32_t(i)), t);
    for (int c = 0; c < 3; ++c) {
      mesh.tangents[3 * i + c] = float(t[c]);
      mesh.bitangents[3 * i + c] = float(b[c]);
    }
  }
}

void generate_tangents(ImportedMesh& mesh) {
  const std::size_t corners = mesh.triangles.size();
  const bool normals = !mesh.normals.empty();
  std::vector<glm::dvec3> normal(corners), tangent(corners, glm::dvec3(0.0));
  std::vector<double> weight(corners, 0.0);
  std::vector<bool> preserving(corners, true);
  for (std::size_t f = 0; f < corners; f += 3) {
    const std::uint32_t* v = &mesh.triangles[f];
    glm::dvec3 p[3];
    glm::dvec2 uv[3];
    for (int c = 0; c < 3; ++c) {
      p[c] = vec3_at(mesh.positions, v[c]);
      uv[c] = glm::dvec2(mesh.uv[2 * v[c]], mesh.uv[2 * v[c] + 1]);
    }
    glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    glm::dvec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
    double area_uv = d1.x * d2.y - d2.x * d1.y;
    // dp/du = (d2.v e1 - d1.v e2) / area_uv; only its direction is used.
    glm::dvec3 dp_du = (d2.y * e1 - d1.y * e2) * (area_uv < 0.0 ? -1.0 : 1.0);
    glm::dvec3 face_n = normalized_or_zero(glm::cross(e1, e2));
    for (int c = 0; c < 3; ++c) {
      std::size_t k = f + c;
      preserving[k] = area_uv < 0.0;  // positive with v mirrored
      normal[k] = normals ? normalized_or_zero(vec3_at(mesh.normals, v[c])) : face_n;
      const glm::dvec3& n = normal[k];
      glm::dvec3 t = normalized_or_zero(dp_du - n * glm::dot(n, dp_du));
      glm::dvec3 a = p[(c + 1) % 3] - p[c], b = p[(c + 2) % 3] - p[c];
      a = normalized_or_zero(a - n * glm::dot(n, a));
      b = normalized_or_zero(b - n * glm::dot(n, b));
      double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
      if (area_uv != 0.0 && t != glm::dvec3(0.0) && std::isfinite(angle)) {
        tangent[k] = t;
        weight[k] = angle;
      }
    }
  }

  auto key_of = [&](std::size_t k, bool orientation) {
    std::uint32_t v = mesh.triangles[k];
    glm::dvec3 p = vec3_at(mesh.positions, v);
    return CornerKey{bits(p.x),
                     bits(p.y),
                     bits(p.z),
                     bits(normal[k].x),
                     bits(normal[k].y),
                     bits(normal[k].z),
                     bits(mesh.uv[2 * v]),
                     bits(mesh.uv[2 * v + 1]),
                     orientation};
  };
  std::map<CornerKey, glm::dvec3> sums;
  for (std::size_t k = 0; k < corners; ++k)
    if (weight[k] > 0.0) sums[key_of(k, preserving[k])] += weight[k] * tangent[k];

  // Per corner: tangent and bitangent; then one vertex per (vertex, frame).
  std::map<std::array<std::uint32_t, 7>, std::uint32_t> split;
  ImportedMesh out;
  out.material = mesh.material;
  for (std::size_t k = 0; k < corners; ++k) {
    bool orientation = preserving[k];
    glm::dvec3 t(0.0);
    for (bool o : {orientation, !orientation}) {
      auto it = sums.find(key_of(k, o));
      if (it != sums.end() && (t = normalized_or_zero(it->second)) != glm::dvec3(0.0)) {
        orientation = o;
        break;
      }
    }
    const glm::dvec3& n = normal[k];
    if (t == glm::dvec3(0.0)) {
      Frame basis = frame_from_normal(vec3(n));
      t = n == glm::dvec3(0.0) ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(basis.s);
      orientation = true;
    }
    glm::dvec3 b = (orientation ? 1.0 : -1.0) * glm::cross(n, t);
    if (b == glm::dvec3(0.0)) b = glm::dvec3(0.0, 1.0, 0.0);
    std::uint32_t v = mesh.triangles[k];
    std::array<std::uint32_t, 7> id{v,         bits(t.x), bits(t.y), bits(t.z),
                                    bits(b.x), bits(b.y), bits(b.z)};
    auto [it, added] = split.try_emplace(id, std::uint32_t(out.positions.size() / 3));
    if (added) {
      for (int c = 0; c < 3; ++c) {
        out.positions.push_back(mesh.positions[3 * v + c]);
        if (normals) out.normals.push_back(mesh.normals[3 * v + c]);
        out.tangents.push_back(float(t[c]));
        out.bitangents.push_back(float(b[c]));
      }
      out.uv.push_back(mesh.uv[2 * v]);
      out.uv.push_back(mesh.uv[2 * v + 1]);
    }
    out.triangles.push_back(it->second);
  }
  mesh = std::move(out);
}

}  // namespace tr
