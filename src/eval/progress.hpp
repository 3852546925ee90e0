#pragma once
// A one-line progress bar on stderr (only when stderr is a terminal): done/total and time left.
#include <chrono>
#include <string>

#include "scene/generation_progress.hpp"
#include "tables/table_cache.hpp"

namespace glintlab {

class ProgressBar {
 public:
  /// `unit`: what done/total count ("tiles", "marginals"); `start`: when the work began.
  ProgressBar(std::string label, bool enabled, std::string unit = "tiles",
              std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());
  void update(int done, int total);
  ~ProgressBar();

 private:
  std::string label_;
  std::string unit_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

/// Table generation shown as a progress bar per table (when `show_progress`), warnings on stderr.
TableObserver terminal_table_observer(bool show_progress);

/// Slow scene generation (a large procedural normal map) as a progress bar, drawn only once a
/// generation has run for a second (when `show_progress`), so quick ones stay silent.
GenerationObserver terminal_generation_observer(bool show_progress);

}  // namespace glintlab
