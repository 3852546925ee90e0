#pragma once
// A one-line progress bar on stderr (only when stderr is a terminal): done/total and time left.
#include <chrono>
#include <string>

namespace glintlab {

class ProgressBar {
 public:
  ProgressBar(std::string label, bool enabled);
  void update(int done, int total);
  ~ProgressBar();

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace glintlab
