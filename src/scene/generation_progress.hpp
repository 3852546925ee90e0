#pragma once
// Progress of slow scene generation (a large procedural normal map). As Mitsuba 3's
// ProgressReporter reports to its thread's Logger, a generator reports to the observer that the
// caller installed on its thread for the scope of a scene load, so the parser passes nothing
// through; with none installed generation is silent.
#include <functional>
#include <string>

namespace glintlab {

/// `what` is being generated; `done` of `total` steps are finished (reported from 0 to total).
using GenerationObserver = std::function<void(const std::string& what, int done, int total)>;

/// Installs `observer` on this thread while it lives, then restores the previous one.
class ScopedGenerationObserver {
 public:
  explicit ScopedGenerationObserver(GenerationObserver observer);
  ~ScopedGenerationObserver();
  ScopedGenerationObserver(const ScopedGenerationObserver&) = delete;
  ScopedGenerationObserver& operator=(const ScopedGenerationObserver&) = delete;

 private:
  GenerationObserver previous_;
};

/// Tells this thread's observer, if any.
void report_generation_progress(const std::string& what, int done, int total);

}  // namespace glintlab
