#include "scenes/ply_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace tr {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("PLY: " + what); }

// The scalar types under both of the format's spellings.
PlyScalar scalar_type(const std::string& t) {
  struct Entry {
    int size;
    bool floating, is_signed;
  };
  static const std::map<std::string, Entry> types = {
      {"char", {1, false, true}},    {"int8", {1, false, true}},    {"uchar", {1, false, false}},
      {"uint8", {1, false, false}},  {"short", {2, false, true}},   {"int16", {2, false, true}},
      {"ushort", {2, false, false}}, {"uint16", {2, false, false}}, {"int", {4, false, true}},
      {"int32", {4, false, true}},   {"uint", {4, false, false}},   {"uint32", {4, false, false}},
      {"float", {4, true, true}},    {"float32", {4, true, true}},  {"double", {8, true, true}},
      {"float64", {8, true, true}}};
  auto it = types.find(t);
  if (it == types.end()) fail("unknown property type '" + t + "'");
  PlyScalar s;
  s.size = it->second.size;
  s.floating = it->second.floating;
  s.is_signed = it->second.is_signed;
  if (!s.floating) s.integer_max = std::ldexp(1.0, 8 * s.size - (s.is_signed ? 1 : 0)) - 1.0;
  return s;
}

enum class Format { Ascii, LittleEndian, BigEndian };

// Reads binary values of `type` at data[offset]; throws when they run past the end.
class BinaryBody {
 public:
  BinaryBody(const std::string& data, size_t offset, bool big_endian)
      : data_(data), offset_(offset), big_(big_endian) {}

  double read(const PlyScalar& type) {
    const int n = type.size;
    if (data_.size() - offset_ < size_t(n))
      fail("the file ends before the data its header declares");
    unsigned char b[8];
    std::memcpy(b, data_.data() + offset_, n);
    offset_ += n;
    if (big_) std::reverse(b, b + n);
    if (type.floating) {
      if (n == 4) {
        float f;
        std::memcpy(&f, b, 4);
        return f;
      }
      double d;
      std::memcpy(&d, b, 8);
      return d;
    }
    std::uint64_t u = 0;
    std::memcpy(&u, b, n);
    if (type.is_signed && n < 8 && (u >> (8 * n - 1)) & 1u) u |= ~std::uint64_t(0) << (8 * n);
    return type.is_signed ? double(std::int64_t(u)) : double(u);
  }
  size_t offset() const { return offset_; }

 private:
  const std::string& data_;
  size_t offset_;
  bool big_;
};

}  // namespace

std::vector<PlyElement> read_ply_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) fail("cannot open the file");
  std::string data(size_t(in.tellg()), '\0');
  in.seekg(0);
  if (!in.read(data.data(), std::streamsize(data.size()))) fail("cannot read the file");

  // Header: up to "end_header".
  size_t pos = 0;
  auto next_line = [&](std::string& line) {
    size_t end = data.find('\n', pos);
    if (end == std::string::npos) fail("the header has no end_header line");
    line = data.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    pos = end + 1;
  };
  std::string line;
  next_line(line);
  if (line != "ply") fail("the file does not start with 'ply'");
  Format format = Format::Ascii;
  bool have_format = false;
  std::vector<PlyElement> elements;
  for (;;) {
    next_line(line);
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "end_header") break;
    if (word == "comment" || word == "obj_info" || word.empty()) continue;
    if (word == "format") {
      std::string f;
      words >> f;
      if (f == "ascii")
        format = Format::Ascii;
      else if (f == "binary_little_endian")
        format = Format::LittleEndian;
      else if (f == "binary_big_endian")
        format = Format::BigEndian;
      else
        fail("unknown format '" + f + "'");
      have_format = true;
    } else if (word == "element") {
      PlyElement e;
      std::string count;
      words >> e.name >> count;
      if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos ||
          count.size() > 12)
        fail("element '" + e.name + "' has no valid count ('" + count + "')");
      e.count = std::stoull(count);
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty()) fail("a property before any element");
      PlyProperty p;
      std::string type;
      words >> type;
      if (type == "list") {
        words >> p.count_type >> p.type >> p.name;
        p.count_scalar = scalar_type(p.count_type);
      } else {
        p.type = type;
        words >> p.name;
      }
      p.scalar = scalar_type(p.type);
      if (p.name.empty()) fail("a property without a name");
      elements.back().properties.push_back(p);
    } else {
      fail("unexpected header line '" + line + "'");
    }
  }
  if (!have_format) fail("the header has no format line");

  // What a triangle mesh needs (Mitsuba's ply.cpp asks the same): vertices with scalar x, y, z,
  // and faces, if any, as a list of vertex indices.
  std::uint64_t vertices = 0;
  bool have_vertices = false;
  for (const PlyElement& e : elements) {
    auto has = [&](const char* name, bool list) {
      for (const PlyProperty& p : e.properties)
        if (p.name == name && p.count_type.empty() != list) return true;
      return false;
    };
    if (e.name == "vertex") {
      if (!has("x", false) || !has("y", false) || !has("z", false))
        fail("the vertex element lacks one of the scalar properties x, y, z");
      vertices = e.count;
      have_vertices = true;
    } else if (e.name == "face" && !has("vertex_indices", true) && !has("vertex_index", true)) {
      fail("the face element has no list property vertex_indices");
    }
  }
  if (!have_vertices) fail("the file has no vertex element");
  auto is_face_indices = [](const PlyElement& e, const PlyProperty& p) {
    return e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
  };
  // Per element, which of its properties is the face's vertex index list.
  std::vector<std::vector<char>> face_index_list(elements.size());
  for (size_t i = 0; i < elements.size(); ++i)
    for (const PlyProperty& p : elements[i].properties)
      face_index_list[i].push_back(is_face_indices(elements[i], p));
  auto add_face_size = [&](PlyElement& e, double n) {
    if (n < 3.0) fail("a face with " + std::to_string(std::int64_t(n)) + " vertices (at least 3)");
    e.face_sizes.push_back(std::uint32_t(n));
  };
  auto add_index = [&](PlyElement& e, double v) {
    if (!(v >= 0.0 && v < double(vertices)))
      fail("face vertex index " + std::to_string(std::int64_t(v)) + " outside the " +
           std::to_string(vertices) + " vertices");
    e.face_indices.push_back(std::uint32_t(v));
  };
  for (PlyElement& e : elements) e.columns.resize(e.properties.size());

  if (format == Format::Ascii) {
    std::istringstream body(data.substr(pos));
    std::string token;
    auto value = [&]() {
      if (!(body >> token)) fail("the file ends before the data its header declares");
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (*end != '\0') fail("'" + token + "' is not a number");
      return v;
    };
    for (size_t j = 0; j < elements.size(); ++j) {
      PlyElement& e = elements[j];
      for (std::uint64_t i = 0; i < e.count; ++i)
        for (size_t k = 0; k < e.properties.size(); ++k) {
          if (e.properties[k].count_type.empty()) {
            e.columns[k].push_back(value());
            continue;
          }
          const double n = value();
          if (!(n >= 0.0) || n > 1e9) fail("a list length of " + token);
          const bool indices = face_index_list[j][k];
          if (indices) add_face_size(e, n);
          for (std::uint64_t c = 0; c < std::uint64_t(n); ++c) {
            const double v = value();
            if (indices) add_index(e, v);
          }
        }
    }
    return elements;
  }

  BinaryBody body(data, pos, format == Format::BigEndian);
  for (size_t j = 0; j < elements.size(); ++j) {
    PlyElement& e = elements[j];
    bool fixed = true;
    std::uint64_t item_bytes = 0;
    for (const PlyProperty& p : e.properties) {
      fixed &= p.count_type.empty();
      item_bytes += std::uint64_t(p.scalar.size);
    }
    // Fixed-size items: the length is known before anything is allocated.
    if (fixed && e.count > (data.size() - body.offset()) / std::max<std::uint64_t>(item_bytes, 1))
      fail("the file ends before the data its header declares");
    if (fixed)
      for (std::vector<double>& column : e.columns) column.reserve(e.count);
    // Faces: each item holds at least a triangle's indices, so the file bounds the count of
    // faces and the reservation follows the header only where the file can hold it.
    std::uint64_t face_min_bytes = 0;
    for (size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      face_min_bytes += face_index_list[j][k]
                            ? std::uint64_t(p.count_scalar.size + 3 * p.scalar.size)
                        : p.count_type.empty() ? std::uint64_t(p.scalar.size)
                                               : std::uint64_t(p.count_scalar.size);
    }
    if (e.name == "face" &&
        e.count <= (data.size() - body.offset()) / std::max<std::uint64_t>(face_min_bytes, 1)) {
      e.face_sizes.reserve(e.count);
      e.face_indices.reserve(3 * e.count);
    }
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (p.count_type.empty()) {
          e.columns[k].push_back(body.read(p.scalar));
          continue;
        }
        const double n = body.read(p.count_scalar);
        if (!(n >= 0.0)) fail("a negative list length");
        const bool indices = face_index_list[j][k];
        if (indices) add_face_size(e, n);
        for (std::uint64_t c = 0; c < std::uint64_t(n); ++c) {
          const double v = body.read(p.scalar);
          if (indices) add_index(e, v);
        }
      }
  }
  return elements;
}

}  // namespace tr
