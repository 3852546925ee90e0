// GpuTimer: the wall time covers the work it runs; the GPU time is a finite, non-negative number
// of milliseconds (on llvmpipe it misses the rasterisation, so nothing more is asserted).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "gl/gpu_timer.hpp"
#include "gl_fixture.hpp"

using namespace glintlab;

TEST(GpuTimer, WallTimeCoversTheWorkAndGpuTimeIsMeasured) {
  test::context();
  GpuTimer timer;
  const GpuTime idle = timer.time([] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); });
  EXPECT_GE(idle.wall_ms, 20.0);
  EXPECT_GE(idle.gpu_ms, 0.0);
  // Work the GL must do: clearing a large texture many times.
  gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, GL_RGBA32F, 1024, 1024);
  const float value[4] = {1, 2, 3, 4};
  const GpuTime busy = timer.time([&] {
    for (int i = 0; i < 20; ++i) glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, value);
  });
  check_gl("timing texture clears");
  EXPECT_GT(busy.wall_ms, 0.0);
  EXPECT_GE(busy.gpu_ms, 0.0);
  EXPECT_LT(busy.gpu_ms, 1e6);
}
