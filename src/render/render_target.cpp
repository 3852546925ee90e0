#include "render/render_target.hpp"

#include <glm/vec4.hpp>
#include <vector>

#include "core/error.hpp"
#include "gl/context.hpp"

namespace glintlab {

RenderTarget::RenderTarget(int width, int height) : width_(width), height_(height) {
  total_ = gl::make_texture(GL_TEXTURE_2D);
  specular_ = gl::make_texture(GL_TEXTURE_2D);
  depth_ = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(total_.id(), 1, GL_RGBA32F, width, height);
  glTextureStorage2D(specular_.id(), 1, GL_RGBA32F, width, height);
  glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
  fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, total_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, specular_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo_.id(), 2, buffers);
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
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, zero);
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
