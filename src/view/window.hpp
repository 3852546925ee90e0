#pragma once
// The viewer's window: GLFW with an OpenGL 4.5 core context, and Dear ImGui drawn into it. The
// renderer draws into its own targets in this same context (GlContext::adopt_current), so what
// the window shows comes from the code path `glintlab render` uses.
#include <string>

#include "core/image.hpp"

struct GLFWwindow;

namespace glintlab {

class ViewWindow {
 public:
  /// Opens a window of `width` x `height` screen pixels and makes its context current. Throws
  /// RuntimeFailure naming what is missing (no display: run under xvfb-run; no OpenGL 4.5).
  ViewWindow(int width, int height, const std::string& title);
  ~ViewWindow();
  ViewWindow(const ViewWindow&) = delete;
  ViewWindow& operator=(const ViewWindow&) = delete;

  /// What made the context, for GlContext::adopt_current: "GLFW window (X11)".
  [[nodiscard]] std::string platform() const;
  [[nodiscard]] bool should_close() const;
  void request_close();
  [[nodiscard]] GLFWwindow* handle() const { return window_; }

  /// Polls events and starts an ImGui frame.
  void begin_frame();
  /// Draws ImGui into the window's framebuffer (not yet shown).
  void render_ui();
  /// Shows the frame.
  void present();
  /// The window's framebuffer as drawn (after render_ui, before present): the whole window,
  /// controls included, display-encoded, row 0 at the top.
  [[nodiscard]] Image read_window() const;

 private:
  void close();

  GLFWwindow* window_ = nullptr;
  bool imgui_context_ = false, imgui_glfw_ = false, imgui_opengl_ = false;
};

}  // namespace glintlab
