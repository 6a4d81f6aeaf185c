// Deterministic uniform numbers for the tests: SplitMix64 (Steele, Lea & Flood, "Fast
// Splittable Pseudorandom Number Generators", OOPSLA 2014), floats from the top 24 bits so
// every value is exactly representable and lies in [0, 1).
#ifndef TWINRAY_VALIDATION_RANDOM_H
#define TWINRAY_VALIDATION_RANDOM_H

#include <cstdint>
#include <glm/vec2.hpp>

namespace twinray::validation::detail {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next_bits() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  float uniform() { return float(next_bits() >> 40) * 0x1.0p-24f; }
  glm::vec2 uniform2() {
    float a = uniform();
    return {a, uniform()};
  }

 private:
  std::uint64_t state_;
};

}  // namespace twinray::validation::detail

#endif
