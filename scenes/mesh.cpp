#include "scenes/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "io/srgb.h"
#include "scenes/ply_check.h"

namespace tr {

namespace {

// A PLY property as Mitsuba's StructConverter turns it into a float. src/shapes/ply.h flags
// the integer types from Int8 to UInt64 of its Struct::Type enum Normalized | Gamma: they are
// divided by their type's largest value and sRGB-decoded. That range of the enum
// (UInt8, Int8, UInt16, ..., UInt64, Int64) leaves out UInt8: uchar values are taken as they
// are (255 stays 255), as are floating-point ones (rounded to float).
float ply_float(const PlyProperty& p, double value) {
  if (p.scalar.floating || (p.scalar.size == 1 && !p.scalar.is_signed)) return float(value);
  return srgb_decode(float(value / p.scalar.integer_max));
}

// Mitsuba's grouping of the PLY properties a mesh does not use otherwise into named attributes
// (find_other_fields in src/shapes/ply.h), for the element whose attributes are `prefix`*
// ("vertex_" or "face_"): r, g, b (or red, green, blue), with a or alpha if present, become
// prefix + "color"; runs of consecutive properties name_x, name_y, name_z (or _r _g _b, _0 _1 _2,
// _1 _2 _3; one or three of them) become prefix + name, + "_color" for the r, g, b scheme.
// Mitsuba's warnings are its log's only; here the properties it ignores are left out likewise.
// Returns, per attribute, its name and the properties it reads, in order.
std::vector<std::pair<std::string, std::vector<size_t>>> ply_attribute_groups(
    const PlyElement& e, const std::string& prefix, std::vector<std::string> reserved) {
  std::vector<std::string> names;
  for (const PlyProperty& p : e.properties) names.push_back(p.count_type.empty() ? p.name : "");
  auto find = [&](const std::string& name) -> size_t {
    auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? names.size() : size_t(it - names.begin());
  };
  auto has = [&](const char* name) { return find(name) != names.size(); };
  if (!(has("r") && has("g") && has("b")) && has("red") && has("green") && has("blue")) {
    names[find("red")] = "r";
    names[find("green")] = "g";
    names[find("blue")] = "b";
    if (has("alpha")) names[find("alpha")] = "a";
  }
  std::vector<std::pair<std::string, std::vector<size_t>>> groups;
  if (has("r") && has("g") && has("b")) {
    std::vector<size_t> fields = {find("r"), find("g"), find("b")};
    if (has("a")) fields.push_back(find("a"));
    groups.push_back({prefix + "color", fields});
  }
  reserved.insert(reserved.end(), {"r", "g", "b", "a"});

  const char* postfixes[4] = {"xr01", "yg12", "zb23", "wa34"};
  std::vector<std::string> prefixes_seen;
  std::string current;
  size_t scheme = 0, level = 0;
  bool reading = false;
  auto reset = [&]() {
    current.clear();
    scheme = level = 0;
    reading = false;
  };
  auto flush = [&]() {
    if (level == 1 || level == 3) {
      std::vector<size_t> fields;
      for (size_t k = 0; k < level; ++k) {
        size_t f = find(current + "_" + postfixes[k][scheme]);
        if (f == names.size())
          throw std::runtime_error("PLY: attribute " + prefix + current + " has no property " +
                                   current + "_" + postfixes[k][scheme]);
        fields.push_back(f);
      }
      groups.push_back({prefix + current + (scheme == 1 ? "_color" : ""), fields});
      prefixes_seen.push_back(current);
    }
    reset();
  };
  // The loop below reproduces Mitsuba's, including how it skips a repeated or broken run.
  auto starts_with = [](const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; };
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    if (name.empty() || std::find(reserved.begin(), reserved.end(), name) != reserved.end())
      continue;
    size_t pos = name.find_last_of('_');
    if (pos == std::string::npos || name.size() - pos - 1 != 1) {
      if (reading) flush();
      continue;
    }
    const std::string run = name.substr(0, pos);
    const char c = name[pos + 1];
    if (reading && run != current) flush();
    if (!reading &&
        std::find(prefixes_seen.begin(), prefixes_seen.end(), run) != prefixes_seen.end()) {
      while (i < names.size() && starts_with(names[i], run)) ++i;
      if (i == names.size()) break;
      continue;
    }
    if (!reading) {
      const char* first = std::strchr(postfixes[0], c);
      if (c == '\0' || !first) continue;
      reading = true;
      scheme = size_t(first - postfixes[0]);
      current = run;
    } else if (level >= 4 || c != postfixes[level][scheme]) {
      reset();
      while (i < names.size() && starts_with(names[i], run)) ++i;
      if (i == names.size()) break;
    }
    ++level;
  }
  if (reading) flush();
  return groups;
}

}  // namespace

// Mitsuba's PLY loader (src/shapes/ply.cpp): vertices x, y, z, optional nx, ny, nz (all three)
// and u, v (or texture_u, texture_v, or s, t); faces from the list vertex_indices (or
// vertex_index); other vertex and face properties as mesh attributes (ply_attribute_groups).
// Other elements are skipped, as there. Mitsuba refuses faces of more than 3 corners; twinray
// splits them into a fan of triangles, each with its face's attributes.
TriangleMesh load_ply_mesh(const std::string& path, bool flip_tex_coords) {
  TriangleMesh mesh;
  for (const PlyElement& e : read_ply_file(path)) {
    auto column = [&](const char* name) -> const std::vector<double>* {
      for (size_t k = 0; k < e.properties.size(); ++k)
        if (e.properties[k].name == name && e.properties[k].count_type.empty())
          return &e.columns[k];
      return nullptr;
    };
    auto value = [&](const std::vector<double>* c, size_t i) {
      return ply_float(e.properties[size_t(c - e.columns.data())], (*c)[i]);
    };
    std::vector<std::pair<std::string, std::vector<size_t>>> groups;
    if (e.name == "vertex") {
      const std::vector<double>*x = column("x"), *y = column("y"), *z = column("z");
      const std::vector<double>*nx = column("nx"), *ny = column("ny"), *nz = column("nz");
      const char* uv_names[3][2] = {{"u", "v"}, {"texture_u", "texture_v"}, {"s", "t"}};
      const std::vector<double>*u = nullptr, *v = nullptr;
      std::vector<std::string> reserved = {"x", "y", "z", "nx", "ny", "nz", "u", "v"};
      for (const auto& names : uv_names)
        if (!u && column(names[0]) && column(names[1])) {
          u = column(names[0]);
          v = column(names[1]);
          reserved.insert(reserved.end(), {names[0], names[1]});
        }
      for (size_t i = 0; i < e.count; ++i) {
        mesh.positions.emplace_back(value(x, i), value(y, i), value(z, i));
        if (nx && ny && nz) mesh.normals.emplace_back(value(nx, i), value(ny, i), value(nz, i));
        if (u)
          mesh.uvs.emplace_back(value(u, i), flip_tex_coords ? 1.0f - value(v, i) : value(v, i));
      }
      groups = ply_attribute_groups(e, "vertex_", reserved);
    } else if (e.name == "face") {
      size_t corner = 0;
      for (std::uint32_t n : e.face_sizes) {
        for (std::uint32_t k = 1; k + 1 < n; ++k)
          mesh.indices.insert(
              mesh.indices.end(),
              {e.face_indices[corner], e.face_indices[corner + k], e.face_indices[corner + k + 1]});
        corner += n;
      }
      groups = ply_attribute_groups(e, "face_", {});
    }
    for (const auto& [name, fields] : groups) {
      VertexAttribute& a = mesh.attributes[name];
      a.dim = int(fields.size());
      for (size_t i = 0; i < e.count; ++i) {
        const size_t copies = e.name == "face" ? e.face_sizes[i] - 2 : 1;
        for (size_t c = 0; c < copies; ++c)
          for (size_t f : fields) a.values.push_back(ply_float(e.properties[f], e.columns[f][i]));
      }
    }
  }
  if (mesh.indices.empty()) throw std::runtime_error("the file contains no triangles");
  check_finite(mesh);
  return mesh;
}

void check_finite(const TriangleMesh& mesh) {
  auto finite = [](glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  for (const glm::vec3& p : mesh.positions)
    if (!finite(p)) throw std::runtime_error("a vertex position is NaN or infinite");
  for (const glm::vec3& n : mesh.normals)
    if (!finite(n)) throw std::runtime_error("a vertex normal is NaN or infinite");
  for (const glm::vec2& t : mesh.uvs)
    if (!finite(glm::vec3(t, 0.0f)))
      throw std::runtime_error("a texture coordinate is NaN or infinite");
  for (const auto& [name, attribute] : mesh.attributes)
    for (float v : attribute.values)
      if (!std::isfinite(v)) throw std::runtime_error("a value of " + name + " is NaN or infinite");
}

TriangleMesh make_rectangle() {
  TriangleMesh m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.normals.assign(4, glm::vec3(0, 0, 1));
  for (const glm::vec3& p : m.positions) m.uvs.emplace_back(0.5f * (p.x + 1), 0.5f * (p.y + 1));
  m.indices = {0, 1, 2, 2, 3, 0};
  return m;
}

TriangleMesh make_cube() {
  TriangleMesh m;
  m.positions = {{1, -1, -1}, {1, -1, 1},   {-1, -1, 1}, {-1, -1, -1}, {1, 1, -1},   {-1, 1, -1},
                 {-1, 1, 1},  {1, 1, 1},    {1, -1, -1}, {1, 1, -1},   {1, 1, 1},    {1, -1, 1},
                 {1, -1, 1},  {1, 1, 1},    {-1, 1, 1},  {-1, -1, 1},  {-1, -1, 1},  {-1, 1, 1},
                 {-1, 1, -1}, {-1, -1, -1}, {1, 1, -1},  {1, -1, -1},  {-1, -1, -1}, {-1, 1, -1}};
  const glm::vec3 face_normal[6] = {{0, -1, 0}, {0, 1, 0},  {1, 0, 0},
                                    {0, 0, 1},  {-1, 0, 0}, {0, 0, -1}};
  const glm::vec2 corner_uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (int f = 0; f < 6; ++f) {
    for (int c = 0; c < 4; ++c) {
      m.normals.push_back(face_normal[f]);
      m.uvs.push_back(corner_uv[c]);
    }
    uint32_t b = uint32_t(4 * f);
    m.indices.insert(m.indices.end(), {b, b + 1, b + 2, b + 3, b, b + 2});
  }
  return m;
}

namespace {

// Angle between unit vectors, accurate near 0 and pi (as Mitsuba's unit_angle).
float unit_angle(glm::vec3 a, glm::vec3 b) {
  if (glm::dot(a, b) < 0.0f) return 3.14159265358979f - 2.0f * std::asin(0.5f * glm::length(a + b));
  return 2.0f * std::asin(0.5f * glm::length(a - b));
}

}  // namespace

std::vector<glm::vec3> mesh_vertex_normals(const TriangleMesh& mesh) {
  std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    glm::vec3 v[3] = {mesh.positions[i[0]], mesh.positions[i[1]], mesh.positions[i[2]]};
    glm::vec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
    float len2 = glm::dot(n, n);
    if (!(len2 > 0.0f)) continue;
    n /= std::sqrt(len2);
    for (int k = 0; k < 3; ++k) {
      glm::vec3 e1 = v[(k + 1) % 3] - v[k], e2 = v[(k + 2) % 3] - v[k];
      float angle = unit_angle(glm::normalize(e1), glm::normalize(e2));
      normals[i[k]] += n * angle;
    }
  }
  for (glm::vec3& n : normals) {
    float len = glm::length(n);
    n = len != 0.0f ? n / len : glm::vec3(1, 0, 0);  // Mitsuba's placeholder for unused vertices
  }
  return normals;
}

void transform_mesh(TriangleMesh& mesh, const glm::dmat4& m) {
  glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));
  for (glm::vec3& p : mesh.positions) p = glm::vec3(m * glm::dvec4(glm::dvec3(p), 1.0));
  for (glm::vec3& n : mesh.normals) {
    glm::dvec3 t = normal_matrix * glm::dvec3(n);
    double len = glm::length(t);
    n = len > 0.0 ? glm::vec3(t / len) : n;
  }
}

std::vector<float> mesh_tangent_frames(const TriangleMesh& mesh, const glm::dmat4& to_world) {
  const size_t vertices = mesh.positions.size();
  std::vector<float> frames(6 * vertices);
  const char* names[2] = {"vertex_tangent", "vertex_bitangent"};
  for (size_t k = 0; k < 2; ++k) {
    auto it = mesh.attributes.find(names[k]);
    if (it == mesh.attributes.end() || it->second.dim != 3 ||
        it->second.values.size() != 3 * vertices)
      throw std::runtime_error(std::string("vertex_tangents needs the mesh attribute ") + names[k] +
                               " with 3 values a vertex (PLY properties " +
                               (k == 0 ? "tangent" : "bitangent") + "_x, _y, _z)");
    const std::vector<float>& v = it->second.values;
    for (size_t i = 0; i < vertices; ++i) {
      glm::dvec3 w = glm::dmat3(to_world) * glm::dvec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
      for (int c = 0; c < 3; ++c) frames[3 * (k * vertices + i) + c] = float(w[c]);
    }
  }
  return frames;
}

double triangle_area(const TriangleMesh& mesh, size_t triangle) {
  glm::dvec3 a(mesh.positions[mesh.indices[3 * triangle]]);
  glm::dvec3 b(mesh.positions[mesh.indices[3 * triangle + 1]]);
  glm::dvec3 c(mesh.positions[mesh.indices[3 * triangle + 2]]);
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

}  // namespace tr
