#include "render/render_target.hpp"

#include <glm/vec4.hpp>
#include <vector>

#include "core/error.hpp"
#include "gl/context.hpp"

namespace glintlab {

RenderTarget::RenderTarget(int width, int height, TargetLayout layout)
    : width_(width), height_(height), layout_(layout) {
  if (layout.colour_targets < 0 || layout.colour_targets > 2)
    throw RuntimeFailure("RenderTarget: " + std::to_string(layout.colour_targets) + " colour targets (0 to 2 allowed)");
  fbo_ = gl::make_framebuffer();
  gl::Texture* colour[] = {&total_, &specular_};
  GLenum buffers[] = {GL_NONE, GL_NONE};
  for (int i = 0; i < layout.colour_targets; ++i) {
    *colour[i] = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(colour[i]->id(), 1, layout.colour_format, width, height);
    buffers[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
    glNamedFramebufferTexture(fbo_.id(), buffers[i], colour[i]->id(), 0);
  }
  // The forward pass writes both outputs; an output whose draw buffer is GL_NONE is discarded.
  glNamedFramebufferDrawBuffers(fbo_.id(), 2, buffers);
  depth_ = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RuntimeFailure("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                         " float render target (out of GPU memory?)");
  check_gl("creating a render target");
}

void RenderTarget::bind_and_clear(int viewport_width, int viewport_height) const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, viewport_width > 0 ? viewport_width : width_, viewport_height > 0 ? viewport_height : height_);
  const float zero[4] = {0, 0, 0, 0};
  const float far = 1.0f;
  for (int i = 0; i < layout_.colour_targets; ++i) glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, i, zero);
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
}

Image RenderTarget::read(GLuint texture, int width, int height) {
  std::vector<glm::vec4> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(glm::vec4)), rgba.data());
  check_gl("reading back an image");
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      img.at(x, y) = glm::vec3(rgba[static_cast<std::size_t>(height - 1 - y) * width + x]);
  return img;
}

}  // namespace glintlab
