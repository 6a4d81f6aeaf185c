#include "scenes/obj_file.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace tr {

namespace {

using Key = std::array<std::uint32_t, 3>;  // 1-based (v, vt, vn); 0: none

struct KeyHash {
  size_t operator()(const Key& k) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the three indices
    for (std::uint32_t v : k) h = (h ^ v) * 1099511628211ull;
    return size_t(h);
  }
};

[[noreturn]] void fail(size_t line, const std::string& what) {
  throw std::runtime_error("line " + std::to_string(line) + ": " + what);
}

// Mitsuba's string::strtof: skips spaces and tabs and a '+', then a decimal number as
// std::from_chars reads it (fast_float there); false when none is there or it is out of range.
bool parse_float(const char*& cur, const char* end, float& value) {
  const char* p = cur;
  while (*p == ' ' || *p == '\t') ++p;
  if (*p == '+') ++p;
  auto [next, ec] = std::from_chars(p, end, value);
  if (ec != std::errc()) return false;
  cur = next;
  return true;
}

template <int N>
std::array<float, N> parse_floats(const char*& cur, const char* end, size_t line) {
  std::array<float, N> v{};
  for (float& x : v)
    if (!parse_float(cur, end, x)) fail(line, "expected " + std::to_string(N) + " numbers");
  return v;
}

// strtoul(…, 10) as Mitsuba reads a face index (leading white space and a sign allowed), but
// refusing a negative index (Mitsuba fails on its wrapped value) and one beyond 32 bits (which
// Mitsuba would wrap).
bool parse_index(const char*& cur, std::uint32_t& value, size_t line) {
  const char* p = cur;
  while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n' || *p == '\v' || *p == '\f') ++p;
  bool negative = *p == '-';
  if (*p == '+' || *p == '-') ++p;
  if (*p < '0' || *p > '9') return false;
  std::uint64_t v = 0;
  for (; *p >= '0' && *p <= '9'; ++p) {
    v = 10 * v + std::uint64_t(*p - '0');
    if (v > UINT32_MAX) fail(line, "face index beyond 32 bits");
  }
  if (negative && v != 0)
    fail(line, "relative face index -" + std::to_string(v) + " (not supported, as in Mitsuba)");
  value = std::uint32_t(v);
  cur = p;
  return true;
}

class ObjReader {
 public:
  ObjReader(bool flip_tex_coords, bool face_normals)
      : flip_tex_coords_(flip_tex_coords), face_normals_(face_normals) {}

  void read_line(const char* cur, const char* end, size_t line) {
    while (*cur == ' ' || *cur == '\t' || *cur == '\r') ++cur;
    auto is_blank = [](char c) { return c == ' ' || c == '\t'; };
    if (cur[0] == 'v' && is_blank(cur[1])) {
      cur += 2;
      auto [x, y, z] = parse_floats<3>(cur, end, line);
      if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
        fail(line, "vertex position is NaN or infinite");
      positions_.emplace_back(x, y, z);
    } else if (cur[0] == 'v' && cur[1] == 'n' && is_blank(cur[2])) {
      if (face_normals_) return;
      cur += 3;
      auto [x, y, z] = parse_floats<3>(cur, end, line);
      glm::vec3 n(x, y, z);
      // Mitsuba normalizes it: NaN for a zero or non-finite normal, which it refuses.
      if (!(std::isfinite(glm::dot(n, n)) && glm::dot(n, n) > 0.0f))
        fail(line, "vertex normal is zero, NaN or infinite");
      normals_.push_back(n);
    } else if (cur[0] == 'v' && cur[1] == 't' && is_blank(cur[2])) {
      cur += 3;
      auto [u, v] = parse_floats<2>(cur, end, line);
      texcoords_.emplace_back(u, flip_tex_coords_ ? 1.0f - v : v);
    } else if (cur[0] == 'f' && is_blank(cur[1])) {
      read_face(cur + 2, line);
    }
  }

  TriangleMesh finish() {
    if (triangles_.empty()) throw std::runtime_error("the file contains no triangles");
    TriangleMesh mesh;
    const bool uvs = !texcoords_.empty(), normals = !face_normals_ && !normals_.empty();
    mesh.positions.resize(keys_.size());
    if (uvs) mesh.uvs.resize(keys_.size());
    if (normals) mesh.normals.resize(keys_.size());
    for (size_t i = 0; i < keys_.size(); ++i) {
      const Key& k = keys_[i];
      mesh.positions[i] = positions_[k[0] - 1];
      if (uvs) mesh.uvs[i] = texcoords_[checked(k[1], texcoords_.size(), i, "texture coordinate")];
      if (normals) mesh.normals[i] = normals_[checked(k[2], normals_.size(), i, "normal")];
    }
    mesh.indices = std::move(triangles_);
    check_finite(mesh);  // texture coordinates, which Mitsuba does not check
    return mesh;
  }

 private:
  // Mitsuba's face loop: a number fills the key's slot the '/'s before it chose; a corner ends
  // at white space or the line's end; anything else ends the face.
  void read_face(const char* cur, size_t line) {
    Key key{0, 0, 0};
    size_t slot = 0, corners = 0;
    std::uint32_t tri[3];
    while (true) {
      std::uint32_t value;
      if (!parse_index(cur, value, line)) break;
      if (slot >= 3) fail(line, "a face corner has more than v/vt/vn");
      key[slot] = value;
      while (*cur == '/') ++slot, ++cur;
      if (*cur != ' ' && *cur != '\t' && *cur != '\0' && *cur != '\r') continue;
      slot = 0;
      if (key[0] == 0 || key[0] > positions_.size())
        fail(line, "reference to vertex " + std::to_string(key[0]) + ", but " +
                       std::to_string(positions_.size()) + " are defined above it");
      auto [it, inserted] = ids_.emplace(key, std::uint32_t(keys_.size()));
      if (inserted) {
        keys_.push_back(key);
        key_lines_.push_back(line);
      }
      if (corners < 3) {
        tri[corners] = it->second;
      } else {
        tri[1] = tri[2];
        tri[2] = it->second;
      }
      if (++corners >= 3) triangles_.insert(triangles_.end(), tri, tri + 3);
    }
  }

  size_t checked(std::uint32_t index, size_t count, size_t vertex, const char* what) const {
    if (index == 0)
      fail(key_lines_[vertex], std::string("a face corner without a ") + what +
                                   " in a file that has them (Mitsuba would read "
                                   "uninitialized memory)");
    if (index > count)
      fail(key_lines_[vertex], std::string("reference to ") + what + " " + std::to_string(index) +
                                   ", but the file has " + std::to_string(count));
    return index - 1;
  }

  bool flip_tex_coords_, face_normals_;
  std::vector<glm::vec3> positions_, normals_;
  std::vector<glm::vec2> texcoords_;
  std::unordered_map<Key, std::uint32_t, KeyHash> ids_;
  std::vector<Key> keys_;  // by vertex id
  std::vector<size_t> key_lines_;
  std::vector<std::uint32_t> triangles_;
};

}  // namespace

TriangleMesh read_obj_file(const std::string& path, bool flip_tex_coords, bool face_normals) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  const std::string text = bytes.str();
  ObjReader reader(flip_tex_coords, face_normals);
  char buf[1025];
  size_t line = 0;
  for (size_t start = 0; start < text.size();) {
    ++line;
    size_t stop = text.find('\n', start);
    if (stop == std::string::npos) stop = text.size();
    const size_t size = stop - start;
    if (size >= sizeof(buf) - 1)
      fail(line, "a line of " + std::to_string(size) + " characters (Mitsuba's limit is 1023)");
    text.copy(buf, size, start);
    buf[size] = '\0';
    // Like Mitsuba's copy into a C string, a NUL byte ends the line.
    reader.read_line(buf, buf + std::char_traits<char>::length(buf), line);
    start = stop + 1;
  }
  return reader.finish();
}

}  // namespace tr
