#include "scenes/gltf/gltf_buffers.h"

#include <cstdint>
#include <fstream>
#include <sstream>

#include "scenes/gltf/gltf_json.h"

namespace tr {

using namespace gltf_json;

namespace {

// Base64 (RFC 4648 section 4).
std::string base64(const std::string& s, const std::string& pointer) {
  std::string out;
  uint32_t acc = 0;
  int bits = 0;
  for (char c : s) {
    int v = c >= 'A' && c <= 'Z'   ? c - 'A'
            : c >= 'a' && c <= 'z' ? c - 'a' + 26
            : c >= '0' && c <= '9' ? c - '0' + 52
            : c == '+'             ? 62
            : c == '/'             ? 63
                                   : -1;
    if (c == '=') break;
    if (v < 0) throw GltfFieldError(pointer, "invalid base64 in a data URI");
    acc = (acc << 6) | uint32_t(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += char((acc >> bits) & 0xFF);
    }
  }
  return out;
}

int hex_digit(char c) {
  return c >= '0' && c <= '9'   ? c - '0'
         : c >= 'a' && c <= 'f' ? c - 'a' + 10
         : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                : -1;
}

}  // namespace

GltfBuffers::GltfBuffers(const json& doc,
                         std::function<std::filesystem::path(const std::string&)> resolve,
                         std::string glb_bin, bool has_glb_bin)
    : doc_(doc),
      resolve_(std::move(resolve)),
      glb_bin_(std::move(glb_bin)),
      has_glb_bin_(has_glb_bin) {}

std::string GltfBuffers::uri_bytes(const std::string& uri, const std::string& pointer) const {
  if (uri.rfind("data:", 0) == 0) {
    size_t comma = uri.find(',');
    if (comma == std::string::npos || comma < 7 || uri.compare(comma - 7, 7, ";base64") != 0)
      throw GltfFieldError(pointer, "only base64 data URIs are supported");
    return base64(uri.substr(comma + 1), pointer);
  }
  std::string name;  // percent-decoded (RFC 3986 section 2.1)
  for (size_t i = 0; i < uri.size(); ++i) {
    int hi = i + 2 < uri.size() ? hex_digit(uri[i + 1]) : -1;
    int lo = i + 2 < uri.size() ? hex_digit(uri[i + 2]) : -1;
    if (uri[i] == '%' && hi >= 0 && lo >= 0) {
      name += char(hi * 16 + lo);
      i += 2;
    } else {
      name += uri[i];
    }
  }
  std::filesystem::path file = resolve_(name);
  std::error_code ec;
  if (file.empty() || !std::filesystem::is_regular_file(file, ec))
    throw GltfFieldError(pointer, "file \"" + name + "\" not found");
  std::ifstream in(file, std::ios::binary);
  std::stringstream b;
  b << in.rdbuf();
  if (!in && !in.eof()) throw GltfFieldError(pointer, "cannot read \"" + name + "\"");
  return b.str();
}

const std::string& GltfBuffers::buffer(size_t b) {
  auto done = buffers_.find(b);
  if (done != buffers_.end()) return done->second;
  std::string p = "/buffers/" + std::to_string(b);
  const json& o = object(list(doc_, "buffers")[b], p);
  size_t length = size_t(integer(o, "byteLength", -1, p));
  std::string data;
  if (const json* u = member(o, "uri")) {
    if (!u->is_string()) throw GltfFieldError(p + "/uri", "expected a string");
    data = uri_bytes(u->get<std::string>(), p + "/uri");
  } else if (b == 0 && has_glb_bin_) {
    data = glb_bin_;  // spec "GLB-stored Buffer"
  } else {
    throw GltfFieldError(p, "no \"uri\" and no GLB BIN chunk");
  }
  // Spec "GLB-stored Buffer": the BIN chunk may be up to 3 bytes longer (padding).
  if (data.size() < length)
    throw GltfFieldError(p + "/byteLength", "is " + std::to_string(length) +
                                                " but the buffer holds " +
                                                std::to_string(data.size()) + " bytes");
  data.resize(length);
  return buffers_[b] = std::move(data);
}

std::string_view GltfBuffers::view(size_t v, size_t* stride) {
  std::string p = "/bufferViews/" + std::to_string(v);
  const json& o = object(list(doc_, "bufferViews")[v], p);
  const std::string& data = buffer(reference(doc_, o, "buffer", "buffers", p));
  size_t offset = size_t(integer(o, "byteOffset", 0, p));
  size_t length = size_t(integer(o, "byteLength", -1, p));
  if (offset > data.size() || length > data.size() - offset)
    throw GltfFieldError(p, "bytes " + std::to_string(offset) + ".." +
                                std::to_string(offset + length) + " lie outside the buffer (" +
                                std::to_string(data.size()) + " bytes)");
  if (stride) {
    *stride = size_t(integer(o, "byteStride", 0, p));
    // Spec bufferView.schema.json: byteStride in [4, 252], a multiple of 4.
    if (*stride != 0 && (*stride < 4 || *stride > 252 || *stride % 4 != 0))
      throw GltfFieldError(p + "/byteStride", "must be a multiple of 4 in [4, 252]");
  }
  return std::string_view(data).substr(offset, length);
}

}  // namespace tr
