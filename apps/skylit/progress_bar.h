// A one-line progress bar with the time left, drawn on stderr when it is a terminal.
#pragma once

#include <chrono>
#include <cstdio>

namespace skylit::cli {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

  void update(int done, int total) {
    if (!enabled_ || total <= 0) return;
    const double fraction = static_cast<double>(done) / total;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    constexpr int kWidth = 40;
    const int filled = static_cast<int>(fraction * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kWidth] = '\0';
    std::fprintf(stderr, "\r[%s] %3d%%  %5.1f s left ", bar, static_cast<int>(fraction * 100.0 + 0.5), left);
    if (done == total) std::fprintf(stderr, "\r[%s] 100%%  %5.1f s      \n", bar, elapsed);
    std::fflush(stderr);
  }

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace skylit::cli
