#include "eval/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>

namespace glintlab {

ProgressBar::ProgressBar(std::string label, bool enabled, std::string unit, std::chrono::steady_clock::time_point start)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      enabled_(enabled && ::isatty(STDERR_FILENO)),
      start_(start) {}

void ProgressBar::update(int done, int total) {
  if (!enabled_ || total <= 0) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double left = done > 0 ? elapsed * (total - done) / done : 0.0;
  constexpr int kWidth = 30;
  const int filled = kWidth * done / total;
  std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d %s, %.0f s elapsed, %.0f s left ", label_.c_str(), filled,
               "##############################", kWidth - filled, "", done, total, unit_.c_str(), elapsed, left);
  std::fflush(stderr);
  drawn_ = true;
}

ProgressBar::~ProgressBar() {
  if (drawn_) std::fprintf(stderr, "\n");
}

TableObserver terminal_table_observer(bool show_progress) {
  // One bar per table generated, ended when the table is done.
  auto bar = std::make_shared<std::unique_ptr<ProgressBar>>();
  return {
      .progress =
          [bar, show_progress](const TableSource& table, int done, int total) {
            if (!*bar) *bar = std::make_unique<ProgressBar>("generating table " + table.id, show_progress, "steps");
            (*bar)->update(done, total);
            if (done >= total) bar->reset();
          },
      .warning = [](const TableSource& table, const std::string& message) {
        std::cerr << "glintlab: table " << table.id << ": " << message << "\n";
      },
  };
}

GenerationObserver terminal_generation_observer(bool show_progress) {
  struct State {
    std::chrono::steady_clock::time_point start;
    std::unique_ptr<ProgressBar> bar;
  };
  auto state = std::make_shared<State>();
  return [state, show_progress](const std::string& what, int done, int total) {
    const auto now = std::chrono::steady_clock::now();
    if (done == 0) *state = {now, nullptr};  // a new generation
    if (!state->bar && now - state->start >= std::chrono::seconds(1))
      state->bar = std::make_unique<ProgressBar>("generating " + what, show_progress, "rows", state->start);
    if (state->bar) state->bar->update(done, total);
    if (done >= total) state->bar.reset();
  };
}

}  // namespace glintlab
