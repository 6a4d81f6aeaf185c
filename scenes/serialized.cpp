#include "scenes/serialized.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace tr {

namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the .serialized reader copies little-endian data as it is");
static_assert(sizeof(glm::vec3) == 12 && sizeof(glm::vec2) == 8, "vectors must be packed");

// Mitsuba 3.8 src/shapes/serialized.cpp: MI_FILEFORMAT_HEADER, MI_FILEFORMAT_VERSION_V3/V4 and
// TriMeshFlags. Version 3 stores no mesh name. Of the flags, 3.8 reads only these four: a file
// without DoublePrecision is single precision, HasTangents (0x0004) is unused, and the
// FaceNormals hint (0x0010) is not consulted (only the `face_normals` parameter is).
constexpr uint16_t FORMAT_ID = 0x041C;
constexpr uint16_t VERSION_3 = 0x0003, VERSION_4 = 0x0004;
constexpr uint32_t HAS_NORMALS = 0x0001, HAS_TEXCOORDS = 0x0002, HAS_COLORS = 0x0008,
                   DOUBLE_PRECISION = 0x2000;

// Deflate's largest expansion: a 258-byte match coded in as little as 2 bits, about 1032:1
// (zlib's "technical details", zlib.net/zlib_tech.html).
constexpr uint64_t MAX_INFLATE_RATIO = 1032;

class File {
 public:
  explicit File(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error("not a regular file");
    size_ = std::filesystem::file_size(path, ec);
    in_.open(path, std::ios::binary);
    if (ec || !in_) throw std::runtime_error("cannot open the file");
  }
  uint64_t size() const { return size_; }
  uint64_t left() const { return size_ - pos_; }
  void seek(uint64_t offset) {
    pos_ = offset;
    in_.seekg(std::streamoff(offset));
  }
  // Reads exactly n bytes; a file that ends first is truncated before `what`.
  void read(void* dst, size_t n, const std::string& what) {
    if (n > left()) throw std::runtime_error("truncated file: it ends inside " + what);
    read_some(dst, n);
  }
  size_t read_some(void* dst, size_t n) {
    n = size_t(std::min<uint64_t>(n, left()));
    in_.read(static_cast<char*>(dst), std::streamsize(n));
    if (size_t(in_.gcount()) != n) throw std::runtime_error("read error");
    pos_ += n;
    return n;
  }
  template <typename T>
  T read_value(const std::string& what) {
    T v;
    read(&v, sizeof(T), what);
    return v;
  }

 private:
  std::ifstream in_;
  uint64_t size_ = 0, pos_ = 0;
};

// One mesh's zlib stream (Mitsuba's ZStream: zlib format, 15-bit window), read from the file's
// position on; the stream may run to the end of the file.
class Inflater {
 public:
  explicit Inflater(File& file) : file_(file), in_(1 << 16), out_(1 << 16) {
    if (inflateInit(&z_) != Z_OK) throw std::runtime_error("zlib could not be initialised");
  }
  ~Inflater() { inflateEnd(&z_); }
  Inflater(const Inflater&) = delete;
  Inflater& operator=(const Inflater&) = delete;

  // At most how many bytes the rest of the stream can decompress to: what is buffered, the
  // largest expansion of the compressed bytes left, and a margin for zlib's internal state (a
  // pending match, its bit buffer).
  uint64_t most_bytes_left() const {
    return (out_len_ - out_pos_) + MAX_INFLATE_RATIO * (file_.left() + z_.avail_in) + (1 << 16);
  }

  // Decompresses exactly n bytes; `what` names them in errors.
  void read(void* dst, size_t n, const std::string& what) {
    unsigned char* d = static_cast<unsigned char*>(dst);
    while (n > 0) {
      if (out_pos_ == out_len_ && !fill(what))
        throw std::runtime_error("the zlib stream ends inside " + what +
                                 ": the header's counts exceed the data");
      size_t k = std::min(n, out_len_ - out_pos_);
      std::memcpy(d, out_.data() + out_pos_, k);
      out_pos_ += k;
      d += k;
      n -= k;
    }
  }
  template <typename T>
  T read_value(const std::string& what) {
    T v;
    read(&v, sizeof(T), what);
    return v;
  }

  // Decompresses the rest of the stream, which checks zlib's Adler-32 of all of it, and
  // returns how many bytes followed what was read.
  uint64_t finish(const std::string& what) {
    uint64_t extra = out_len_ - out_pos_;
    while (fill(what)) extra += out_len_;
    out_pos_ = out_len_;
    return extra;
  }

 private:
  // Refills out_; false at the end of the stream.
  bool fill(const std::string& what) {
    out_pos_ = out_len_ = 0;
    while (!ended_ && out_len_ == 0) {
      if (z_.avail_in == 0) {
        size_t got = file_.read_some(in_.data(), in_.size());
        if (got == 0)
          throw std::runtime_error("truncated file: the zlib stream breaks off, reading " + what);
        z_.next_in = in_.data();
        z_.avail_in = uInt(got);
      }
      z_.next_out = out_.data();
      z_.avail_out = uInt(out_.size());
      int r = inflate(&z_, Z_NO_FLUSH);
      if (r == Z_MEM_ERROR) throw std::bad_alloc();
      if (r != Z_OK && r != Z_STREAM_END && !(r == Z_BUF_ERROR && z_.avail_in == 0)) {
        std::string reason = z_.msg             ? z_.msg
                             : r == Z_NEED_DICT ? "it asks for a preset dictionary"
                                                : "zlib error " + std::to_string(r);
        throw std::runtime_error("corrupt zlib stream (" + reason + "), reading " + what);
      }
      out_len_ = out_.size() - z_.avail_out;
      ended_ = r == Z_STREAM_END;
    }
    return out_len_ > 0;
  }

  File& file_;
  z_stream z_{};
  std::vector<unsigned char> in_, out_;
  size_t out_pos_ = 0, out_len_ = 0;
  bool ended_ = false;
};

// Reads `count` vectors stored as floats or doubles. The vector grows step by step as data
// arrives, so a header that claims more than the stream holds fails before memory follows it.
template <typename Vec>
std::vector<Vec> read_vectors(Inflater& z, uint64_t count, bool double_precision,
                              const std::string& what) {
  constexpr size_t dim = sizeof(Vec) / sizeof(float);
  const uint64_t step = uint64_t(1) << 16;
  std::vector<Vec> out;
  std::vector<double> wide;
  for (uint64_t done = 0; done < count;) {
    size_t n = size_t(std::min(step, count - done));
    out.resize(size_t(done) + n);
    if (double_precision) {
      wide.resize(n * dim);
      z.read(wide.data(), wide.size() * sizeof(double), what);
      for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < dim; ++c) out[done + i][int(c)] = float(wide[i * dim + c]);
    } else {
      z.read(&out[done], n * sizeof(Vec), what);
    }
    done += n;
  }
  return out;
}

std::vector<uint32_t> read_indices(Inflater& z, uint64_t count, const std::string& what) {
  const uint64_t step = uint64_t(1) << 18;
  std::vector<uint32_t> out;
  for (uint64_t done = 0; done < count;) {
    size_t n = size_t(std::min(step, count - done));
    out.resize(size_t(done) + n);
    z.read(&out[done], n * sizeof(uint32_t), what);
    done += n;
  }
  return out;
}

// Positions the file at the start of mesh `index` (after its header), through the offset
// dictionary at the end of the file (Mitsuba 3.8 serialized.cpp, the shape_index != 0 branch).
void seek_mesh(File& file, uint16_t version, uint32_t index) {
  const uint64_t size = file.size();
  if (size < 8) throw std::runtime_error("truncated file: no room for the offset dictionary");
  file.seek(size - 4);
  uint32_t count = file.read_value<uint32_t>("the mesh count");
  if (index >= count)
    throw ShapeIndexError("shape_index " + std::to_string(index) +
                          " is out of range: the file's offset dictionary lists " +
                          std::to_string(count) + " meshes");
  const uint64_t entry = version == VERSION_4 ? 8 : 4;
  const uint64_t dictionary = entry * count + 4;
  if (dictionary > size - 4)
    throw std::runtime_error("the offset dictionary claims " + std::to_string(count) +
                             " meshes, more than the file has room for (truncated file?)");
  file.seek(size - 4 - entry * (count - index));
  uint64_t offset = version == VERSION_4 ? file.read_value<uint64_t>("the offset dictionary")
                                         : file.read_value<uint32_t>("the offset dictionary");
  if (offset > size - dictionary - 4)
    throw std::runtime_error("the offset dictionary places mesh " + std::to_string(index) +
                             " at byte " + std::to_string(offset) + ", past the mesh data");
  file.seek(offset);
  uint16_t header[2];
  file.read(header, sizeof(header), "a mesh header");
  // Stricter than Mitsuba, which skips this header unread: a mismatch means the offset is wrong.
  if (header[0] != FORMAT_ID || header[1] != version)
    throw std::runtime_error("no mesh header at byte " + std::to_string(offset) + " where the " +
                             "offset dictionary places mesh " + std::to_string(index));
}

}  // namespace

SerializedMesh load_serialized_mesh(const std::string& path, uint32_t shape_index) {
  File file(path);
  uint16_t header[2];
  file.read(header, sizeof(header), "the file header");
  if (header[0] != FORMAT_ID) {
    char id[8];
    std::snprintf(id, sizeof(id), "0x%04X", unsigned(header[0]));
    throw std::runtime_error(std::string("not a Mitsuba serialized mesh: format identifier ") + id +
                             ", expected 0x041C");
  }
  const uint16_t version = header[1];
  if (version != VERSION_3 && version != VERSION_4)
    throw std::runtime_error("unsupported serialized format version " + std::to_string(version) +
                             " (Mitsuba 3 reads versions 3 and 4)");
  // Mesh 0 follows the header directly; Mitsuba consults the dictionary only for the others.
  if (shape_index != 0) seek_mesh(file, version, shape_index);

  const std::string mesh = "mesh " + std::to_string(shape_index);
  Inflater z(file);
  SerializedMesh out;
  const uint32_t flags = z.read_value<uint32_t>("the flags of " + mesh);
  if (version == VERSION_4)
    for (char c; (c = z.read_value<char>("the name of " + mesh)) != '\0';) out.name += c;
  const uint64_t vertex_count = z.read_value<uint64_t>("the vertex count of " + mesh);
  const uint64_t triangle_count = z.read_value<uint64_t>("the triangle count of " + mesh);

  const bool double_precision = flags & DOUBLE_PRECISION;
  const bool has_normals = flags & HAS_NORMALS, has_uvs = flags & HAS_TEXCOORDS,
             has_colors = flags & HAS_COLORS;
  // Mitsuba keeps counts and indices in 32 bits (Mesh::ScalarSize, ScalarIndex).
  if (vertex_count > std::numeric_limits<uint32_t>::max() ||
      triangle_count > std::numeric_limits<uint32_t>::max() / 3)
    throw std::runtime_error(mesh + " claims " + std::to_string(vertex_count) + " vertices and " +
                             std::to_string(triangle_count) +
                             " triangles, more than 32-bit indices address");
  if (triangle_count == 0) throw std::runtime_error(mesh + " has no triangles");
  const uint64_t floats_per_vertex =
      3 + (has_normals ? 3 : 0) + (has_uvs ? 2 : 0) + (has_colors ? 3 : 0);
  const uint64_t bytes = vertex_count * floats_per_vertex * (double_precision ? 8 : 4) +
                         triangle_count * 3 * sizeof(uint32_t);
  if (bytes > z.most_bytes_left())
    throw std::runtime_error(mesh + " claims " + std::to_string(vertex_count) + " vertices and " +
                             std::to_string(triangle_count) + " triangles (" +
                             std::to_string(bytes) + " bytes), more than the rest of the file " +
                             "can hold (" + std::to_string(z.most_bytes_left()) +
                             " bytes decompressed at most)");

  TriangleMesh& m = out.mesh;
  m.positions =
      read_vectors<glm::vec3>(z, vertex_count, double_precision, "the vertex positions of " + mesh);
  if (has_normals)
    m.normals =
        read_vectors<glm::vec3>(z, vertex_count, double_precision, "the vertex normals of " + mesh);
  if (has_uvs)
    m.uvs = read_vectors<glm::vec2>(z, vertex_count, double_precision,
                                    "the texture coordinates of " + mesh);
  if (has_colors) {
    // Mitsuba 3.8 skips these; they are kept here for textures that read mesh attributes.
    std::vector<glm::vec3> colors =
        read_vectors<glm::vec3>(z, vertex_count, double_precision, "the vertex colors of " + mesh);
    VertexAttribute& a = m.attributes["vertex_color"];
    a.dim = 3;
    a.values.reserve(colors.size() * 3);
    for (const glm::vec3& c : colors) a.values.insert(a.values.end(), {c.x, c.y, c.z});
  }
  m.indices = read_indices(z, triangle_count * 3, "the triangle indices of " + mesh);
  // Stricter than Mitsuba, which stops reading here: the rest of the stream must be empty and
  // pass zlib's checksum, or the flags and counts do not describe the data.
  if (uint64_t extra = z.finish("the end of the zlib stream of " + mesh))
    throw std::runtime_error("the zlib stream of " + mesh + " holds " + std::to_string(extra) +
                             " bytes after its triangle indices: its flags or counts do not " +
                             "describe its data");

  for (size_t i = 0; i < m.indices.size(); ++i)
    if (m.indices[i] >= vertex_count)
      throw std::runtime_error("triangle " + std::to_string(i / 3) + " of " + mesh +
                               " uses vertex " + std::to_string(m.indices[i]) + ", but it has " +
                               std::to_string(vertex_count) + " vertices");
  try {
    check_finite(m);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(mesh + ": " + e.what());
  }
  return out;
}

}  // namespace tr
