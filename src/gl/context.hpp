#pragma once
// An OpenGL 4.5 core context with no display, through EGL: the NVIDIA (or other hardware) EGL
// device when there is one, Mesa's llvmpipe through EGL_PLATFORM_SURFACELESS_MESA otherwise.
// GLINTLAB_GL=software forces llvmpipe, GLINTLAB_GL=hardware refuses it. A window's context (the
// viewer's, made by GLFW) is adopted instead: the same renderer then draws into it.
#include <memory>
#include <string>

namespace glintlab {

struct GlDeviceInfo {
  std::string vendor, renderer, version, glsl_version, egl_platform;
  int max_texture_size = 0, max_array_layers = 0, max_ssbo_bindings = 0, max_compute_invocations = 0,
      max_samples = 0, max_draw_buffers = 0;
  bool timer_query = false;
};

class GlContext {
 public:
  /// Throws RuntimeFailure naming what is missing and which Debian package provides it.
  static std::unique_ptr<GlContext> create_headless();
  /// The context current on this thread, owned by someone else (a window): never destroyed here.
  /// `platform` says what made it (e.g. "GLFW window (X11, GLX)"). Throws RuntimeFailure when no
  /// context is current or it is older than OpenGL 4.5.
  static std::unique_ptr<GlContext> adopt_current(std::string platform);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// Makes a headless context current on this thread again, where a program holds several (the
  /// library's Labs); an adopted context is the window's business: nothing is done.
  void make_current() const;
  [[nodiscard]] GlDeviceInfo info() const;
  [[nodiscard]] bool is_software() const;

 private:
  GlContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string platform_;
};

/// Throws RuntimeFailure with `what` and the GL error if glGetError reports one.
void check_gl(const char* what);

}  // namespace glintlab
