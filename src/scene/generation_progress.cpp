#include "scene/generation_progress.hpp"

#include <utility>

namespace glintlab {

namespace {
thread_local GenerationObserver current_observer;
}  // namespace

ScopedGenerationObserver::ScopedGenerationObserver(GenerationObserver observer)
    : previous_(std::exchange(current_observer, std::move(observer))) {}

ScopedGenerationObserver::~ScopedGenerationObserver() { current_observer = std::move(previous_); }

void report_generation_progress(const std::string& what, int done, int total) {
  if (current_observer) current_observer(what, done, total);
}

}  // namespace glintlab
