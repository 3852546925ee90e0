#pragma once
// Timing GPU work: a GL_TIME_ELAPSED query around it, and the wall clock until the GL has
// finished it. On llvmpipe the query misses the rasterisation (it runs when the frame is read or
// finished), so the wall time is the one to use there (README, "Speed").
#include <functional>

#include "gl/objects.hpp"

namespace glintlab {

struct GpuTime {
  double gpu_ms = 0;   ///< GL_TIME_ELAPSED of the work
  double wall_ms = 0;  ///< the work and glFinish, on the CPU's steady clock
};

class GpuTimer {
 public:
  GpuTimer();
  /// Runs `work` (GL calls), waits until the GL has finished it, and returns both times.
  GpuTime time(const std::function<void()>& work);

 private:
  gl::Query query_;
};

/// Blocks until the GL has finished everything issued so far (glFinish).
void finish_gl_work();

}  // namespace glintlab
