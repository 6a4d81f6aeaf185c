// FNV-1a, 64-bit (Fowler, Noll, Vo; offset basis 14695981039346656037, prime 1099511628211):
// fingerprints of files and scenes for checkpoints, not a cryptographic hash.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace tr {

struct Fnv1a {
  std::uint64_t h = 14695981039346656037ull;

  void add(const void* data, std::size_t bytes) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  // The element count, then the elements' bytes.
  template <typename T>
  void add_vector(const std::vector<T>& v) {
    const std::uint64_t n = v.size();
    add(&n, sizeof n);
    add(v.data(), v.size() * sizeof(T));
  }
  // 16 hex digits.
  std::string hex() const {
    char s[17];
    std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(h));
    return s;
  }
};

}  // namespace tr
