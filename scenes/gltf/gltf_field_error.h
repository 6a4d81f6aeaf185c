// An error about one field of a glTF document: its JSON pointer (RFC 6901) and what is wrong.
// The readers of scenes/gltf/ throw it; the importer turns the pointer into file:line.
#pragma once

#include <stdexcept>
#include <string>

namespace tr {

struct GltfFieldError : std::runtime_error {
  GltfFieldError(std::string field_pointer, const std::string& what)
      : std::runtime_error(what), pointer(std::move(field_pointer)) {}
  std::string pointer;
};

}  // namespace tr
