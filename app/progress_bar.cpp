#include "app/progress_bar.h"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace tr {

ProgressBar::ProgressBar()
    : enabled_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void ProgressBar::update(std::uint64_t done, std::uint64_t total) {
  if (!enabled_ || total == 0) return;
  auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  drawn_ = true;
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double fraction = double(done) / double(total);
  double rate = elapsed > 0.0 ? double(done) / elapsed : 0.0;
  double eta = rate > 0.0 ? double(total - done) / rate : 0.0;
  const int width = 30;
  int filled = int(fraction * width);
  std::string bar(size_t(filled), '#');
  bar.resize(width, '.');
  std::fprintf(stderr, "\r[%s] %5.1f%%  %8.3f Msamples/s  ETA %02d:%02d ", bar.c_str(),
               100.0 * fraction, rate * 1e-6, int(eta) / 60, int(eta) % 60);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (enabled_ && drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace tr
