#include "gl/gpu_timer.hpp"

#include <chrono>

namespace glintlab {

GpuTimer::GpuTimer() : query_(gl::make_query(GL_TIME_ELAPSED)) {}

GpuTime GpuTimer::time(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  glBeginQuery(GL_TIME_ELAPSED, query_.id());
  work();
  glEndQuery(GL_TIME_ELAPSED);
  glFinish();
  const auto end = std::chrono::steady_clock::now();
  GLuint64 ns = 0;
  glGetQueryObjectui64v(query_.id(), GL_QUERY_RESULT, &ns);
  return {static_cast<double>(ns) * 1e-6, std::chrono::duration<double, std::milli>(end - start).count()};
}

void finish_gl_work() { glFinish(); }

}  // namespace glintlab
