#pragma once
// A float HDR render target: total radiance and its specular part (RGBA32F each) plus depth.
#include "core/image.hpp"
#include "gl/objects.hpp"

namespace glintlab {

/// The colour targets of a RenderTarget. Every image glintlab reads back uses the default; the
/// cheaper layouts exist to take the fixed cost of a frame apart (`glintlab bench --floor-breakdown`).
struct TargetLayout {
  GLenum colour_format = GL_RGBA32F;
  int colour_targets = 2;  ///< 2: total and specular; 1: total only; 0: depth only
  auto operator<=>(const TargetLayout&) const = default;
};

class RenderTarget {
 public:
  RenderTarget(int width, int height, TargetLayout layout = {});

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] GLuint framebuffer() const { return fbo_.id(); }
  [[nodiscard]] GLuint total() const { return total_.id(); }
  [[nodiscard]] GLuint specular() const { return specular_.id(); }
  [[nodiscard]] const TargetLayout& layout() const { return layout_; }

  /// Binds for drawing into the whole target (or the given viewport) and clears it.
  void bind_and_clear(int viewport_width = 0, int viewport_height = 0) const;
  /// Reads a colour texture back, row 0 at the top.
  [[nodiscard]] static Image read(GLuint texture, int width, int height);

 private:
  int width_, height_;
  TargetLayout layout_;
  gl::Framebuffer fbo_;
  gl::Texture total_, specular_, depth_;
};

}  // namespace glintlab
