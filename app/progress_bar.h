// Progress of a long render on a terminal: bar, samples/s and ETA, redrawn at most ten times
// a second on stderr; silent when stderr is not a terminal.
#pragma once

#include <chrono>
#include <cstdint>

namespace tr {

class ProgressBar {
 public:
  ProgressBar();
  void update(std::uint64_t done, std::uint64_t total);
  void finish();

 private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace tr
