#include "eval/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace glintlab {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled && ::isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(int done, int total) {
  if (!enabled_ || total <= 0) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double left = done > 0 ? elapsed * (total - done) / done : 0.0;
  constexpr int kWidth = 30;
  const int filled = kWidth * done / total;
  std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d tiles, %.0f s elapsed, %.0f s left ", label_.c_str(), filled,
               "##############################", kWidth - filled, "", done, total, elapsed, left);
  std::fflush(stderr);
  drawn_ = true;
}

ProgressBar::~ProgressBar() {
  if (drawn_) std::fprintf(stderr, "\n");
}

}  // namespace glintlab
