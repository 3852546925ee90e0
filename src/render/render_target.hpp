#pragma once
// A float HDR render target: total radiance and its specular part (RGBA32F each) plus depth.
#include "core/image.hpp"
#include "gl/objects.hpp"

namespace glintlab {

class RenderTarget {
 public:
  RenderTarget(int width, int height);

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] GLuint framebuffer() const { return fbo_.id(); }
  [[nodiscard]] GLuint total() const { return total_.id(); }
  [[nodiscard]] GLuint specular() const { return specular_.id(); }

  /// Binds for drawing into the whole target (or the given viewport) and clears it.
  void bind_and_clear(int viewport_width = 0, int viewport_height = 0) const;
  /// Reads a colour texture back, row 0 at the top.
  [[nodiscard]] static Image read(GLuint texture, int width, int height);

 private:
  int width_, height_;
  gl::Framebuffer fbo_;
  gl::Texture total_, specular_, depth_;
};

}  // namespace glintlab
