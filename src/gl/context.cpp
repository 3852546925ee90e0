#include "gl/context.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

#include "core/error.hpp"

namespace glintlab {

namespace {

constexpr const char* kPackageHint =
    "Debian packages: libegl1 and libegl-mesa0 (EGL), libgl1-mesa-dri (llvmpipe, OpenGL 4.5 in software); "
    "on NVIDIA, the driver's libnvidia-egl and libnvidia-glcore";

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

std::string mode() {
  const char* m = std::getenv("GLINTLAB_GL");
  return m ? m : "auto";
}

/// First hardware EGL device, or EGL_NO_DISPLAY.
EGLDisplay open_hardware_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_EXT_device_enumeration") || !has_extension(client, "EGL_EXT_platform_device"))
    return EGL_NO_DISPLAY;
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return EGL_NO_DISPLAY;
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  eglQueryDevicesEXT(count, devices.data(), &count);
  for (EGLint i = 0; i < count; ++i) {
    const char* ext = eglQueryDeviceStringEXT(devices[static_cast<std::size_t>(i)], EGL_EXTENSIONS);
    if (has_extension(ext, "EGL_MESA_device_software")) continue;
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)], nullptr);
    if (d == EGL_NO_DISPLAY) continue;
    EGLint major = 0, minor = 0;
    if (eglInitialize(d, &major, &minor)) return d;
  }
  return EGL_NO_DISPLAY;
}

EGLDisplay open_surfaceless_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
  EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor)) return EGL_NO_DISPLAY;
  return d;
}

// Live headless contexts per display. EGL gives one display per device and eglTerminate ends
// every context on it, so a display is terminated with its last context: a program (the Python
// module, the library) may hold several contexts at once.
std::mutex display_users_mutex;
std::map<EGLDisplay, int> display_users;

void add_display_user(EGLDisplay display) {
  std::lock_guard lock(display_users_mutex);
  ++display_users[display];
}

// True when no context uses the display any more.
bool remove_display_user(EGLDisplay display) {
  std::lock_guard lock(display_users_mutex);
  if (--display_users[display] > 0) return false;
  display_users.erase(display);
  return true;
}

}  // namespace

std::unique_ptr<GlContext> GlContext::create_headless() {
  const std::string m = mode();
  if (m != "auto" && m != "software" && m != "hardware")
    throw InputError("GLINTLAB_GL: value \"" + m + "\" is not allowed; allowed: auto, software, hardware");
  if (!epoxy_has_egl()) throw RuntimeFailure(std::string("cannot load libEGL; install the ") + kPackageHint);

  std::unique_ptr<GlContext> ctx(new GlContext());
  EGLDisplay display = EGL_NO_DISPLAY;
  if (m != "software") {
    display = open_hardware_display();
    ctx->platform_ = "EGL device";
  }
  if (display == EGL_NO_DISPLAY && m != "hardware") {
    display = open_surfaceless_display();
    ctx->platform_ = "EGL surfaceless (Mesa)";
  }
  if (display == EGL_NO_DISPLAY)
    throw RuntimeFailure(m == "hardware" ? std::string("no hardware EGL device found (GLINTLAB_GL=hardware); ") + kPackageHint
                                         : std::string("no EGL display without a window system could be opened; install the ") + kPackageHint);
  ctx->display_ = display;
  add_display_user(display);
  if (!eglBindAPI(EGL_OPENGL_API)) throw RuntimeFailure("EGL cannot bind the desktop OpenGL API");

  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  const char* dpy_ext = eglQueryString(display, EGL_EXTENSIONS);
  const bool no_config = has_extension(dpy_ext, "EGL_KHR_no_config_context");
  if (!no_config && (!eglChooseConfig(display, config_attribs, &config, 1, &configs) || configs < 1))
    throw RuntimeFailure("EGL has no OpenGL-capable configuration");
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, no_config ? EGL_NO_CONFIG_KHR : config, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) {
    std::ostringstream s;
    s << "cannot create an OpenGL 4.5 core context (EGL error 0x" << std::hex << eglGetError()
      << "); glintlab needs OpenGL 4.5: install the " << kPackageHint;
    throw RuntimeFailure(s.str());
  }
  ctx->context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    throw RuntimeFailure("EGL cannot make a context current without a surface (EGL_KHR_surfaceless_context missing)");
  if (epoxy_gl_version() < 45) throw RuntimeFailure("the OpenGL context is older than 4.5; install the " + std::string(kPackageHint));
  return ctx;
}

std::unique_ptr<GlContext> GlContext::adopt_current(std::string platform) {
  if (glGetString(GL_VERSION) == nullptr) throw RuntimeFailure("no OpenGL context is current to adopt");
  if (epoxy_gl_version() < 45)
    throw RuntimeFailure("the window's OpenGL context is older than 4.5; install the " + std::string(kPackageHint));
  std::unique_ptr<GlContext> ctx(new GlContext());
  ctx->platform_ = std::move(platform);
  return ctx;
}

GlContext::~GlContext() {
  auto display = static_cast<EGLDisplay>(display_);
  if (display != EGL_NO_DISPLAY) {
    if (eglGetCurrentContext() == static_cast<EGLContext>(context_))
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    if (remove_display_user(display)) eglTerminate(display);
  }
}

void GlContext::make_current() const {
  auto display = static_cast<EGLDisplay>(display_);
  if (display == EGL_NO_DISPLAY || eglGetCurrentContext() == static_cast<EGLContext>(context_)) return;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_)))
    throw RuntimeFailure("EGL cannot make glintlab's context current again (EGL error " + std::to_string(eglGetError()) +
                         ")");
}

GlDeviceInfo GlContext::info() const {
  GlDeviceInfo i;
  auto str = [](GLenum e) {
    const auto* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  i.vendor = str(GL_VENDOR);
  i.renderer = str(GL_RENDERER);
  i.version = str(GL_VERSION);
  i.glsl_version = str(GL_SHADING_LANGUAGE_VERSION);
  i.egl_platform = platform_;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &i.max_texture_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &i.max_array_layers);
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &i.max_ssbo_bindings);
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &i.max_compute_invocations);
  glGetIntegerv(GL_MAX_SAMPLES, &i.max_samples);
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &i.max_draw_buffers);
  i.timer_query = epoxy_has_gl_extension("GL_ARB_timer_query") || epoxy_gl_version() >= 33;
  return i;
}

bool GlContext::is_software() const {
  const auto* r = glGetString(GL_RENDERER);
  const std::string s = r ? reinterpret_cast<const char*>(r) : "";
  return s.find("llvmpipe") != std::string::npos || s.find("softpipe") != std::string::npos;
}

void check_gl(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    std::ostringstream s;
    s << "OpenGL error 0x" << std::hex << e << " in " << what;
    throw RuntimeFailure(s.str());
  }
}

}  // namespace glintlab
