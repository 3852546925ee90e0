#pragma once
// RAII owners of OpenGL objects (move-only). Each wraps one name and deletes it on destruction.
#include <epoxy/gl.h>

#include <utility>

namespace glintlab::gl {

template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  [[nodiscard]] GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace detail {
inline void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
inline void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void delete_program(GLuint id) { glDeleteProgram(id); }
inline void delete_shader(GLuint id) { glDeleteShader(id); }
inline void delete_query(GLuint id) { glDeleteQueries(1, &id); }
}  // namespace detail

using Buffer = Handle<detail::delete_buffer>;
using Texture = Handle<detail::delete_texture>;
using Framebuffer = Handle<detail::delete_framebuffer>;
using VertexArray = Handle<detail::delete_vertex_array>;
using Program = Handle<detail::delete_program>;
using Shader = Handle<detail::delete_shader>;
using Query = Handle<detail::delete_query>;

inline Buffer make_buffer(GLsizeiptr size, const void* data, GLbitfield flags = 0) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferStorage(id, size > 0 ? size : 16, data, flags);
  return Buffer(id);
}
inline Texture make_texture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return Texture(id);
}
inline Framebuffer make_framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}
inline VertexArray make_vertex_array() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}
inline Query make_query(GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return Query(id);
}

}  // namespace glintlab::gl
