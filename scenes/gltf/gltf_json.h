// Typed reads of a glTF document's fields for the readers of scenes/gltf/: each failure throws
// GltfFieldError naming the field's JSON pointer.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "scenes/gltf/gltf_field_error.h"

namespace tr::gltf_json {

using json = nlohmann::json;

inline const json* member(const json& o, const char* key) {
  if (!o.is_object()) return nullptr;
  auto it = o.find(key);
  return it == o.end() ? nullptr : &*it;
}

inline const json& object(const json& v, const std::string& pointer) {
  if (!v.is_object())
    throw GltfFieldError(pointer, std::string("expected an object, not ") + v.type_name());
  return v;
}

// The top-level array `key` of `doc` (empty when absent).
inline const json& list(const json& doc, const char* key) {
  static const json empty = json::array();
  const json* v = member(doc, key);
  if (v && !v->is_array())
    throw GltfFieldError(std::string("/") + key,
                         std::string("expected an array, not ") + v->type_name());
  return v ? *v : empty;
}

// A non-negative integer field (or `fallback` when absent and `fallback` >= 0).
inline long long integer(const json& o, const char* key, long long fallback,
                         const std::string& pointer) {
  const json* v = member(o, key);
  std::string p = pointer + "/" + key;
  if (!v) {
    if (fallback < 0) throw GltfFieldError(pointer, std::string("\"") + key + "\" is required");
    return fallback;
  }
  if (!v->is_number_integer() || v->get<long long>() < 0)
    throw GltfFieldError(p, "expected a non-negative integer, not " + v->dump());
  return v->get<long long>();
}

// An index into an array of `count` items.
inline size_t index(const json& v, const std::string& pointer, size_t count) {
  if (!v.is_number_integer())
    throw GltfFieldError(pointer, std::string("expected an index, not ") + v.type_name());
  long long i = v.get<long long>();
  if (i < 0 || size_t(i) >= count)
    throw GltfFieldError(pointer, "index " + std::to_string(i) + " out of range (" +
                                      std::to_string(count) + " items)");
  return size_t(i);
}

// The index field `key` of `o` into the top-level array `array` of `doc`.
inline size_t reference(const json& doc, const json& o, const char* key, const char* array,
                        const std::string& pointer) {
  const json* v = member(o, key);
  if (!v) throw GltfFieldError(pointer, std::string("\"") + key + "\" is required");
  return index(*v, pointer + "/" + key, list(doc, array).size());
}

}  // namespace tr::gltf_json
