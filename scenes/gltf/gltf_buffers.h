// The bytes of a glTF 2.0 file's buffers and buffer views (spec "Buffers and Buffer Views",
// "GLB-stored Buffer", "URIs"), each buffer read once.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace tr {

class GltfBuffers {
 public:
  // `resolve` maps a URI's decoded path to a file (empty when not found); `glb_bin` is the GLB
  // BIN chunk, when `has_glb_bin`.
  GltfBuffers(const nlohmann::json& doc,
              std::function<std::filesystem::path(const std::string&)> resolve, std::string glb_bin,
              bool has_glb_bin);

  // The bytes a URI names: a base64 data URI, or a percent-encoded path relative to the file.
  // Throws GltfFieldError naming `pointer`.
  std::string uri_bytes(const std::string& uri, const std::string& pointer) const;

  // bufferViews[v]: its bytes, checked to lie inside its buffer, and its byteStride (0: none).
  std::string_view view(size_t v, size_t* stride = nullptr);

 private:
  const std::string& buffer(size_t b);

  const nlohmann::json& doc_;
  std::function<std::filesystem::path(const std::string&)> resolve_;
  std::string glb_bin_;
  bool has_glb_bin_;
  std::map<size_t, std::string> buffers_;
};

}  // namespace tr
