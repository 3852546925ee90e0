#include "view/window.hpp"

#include <epoxy/gl.h>
// After epoxy: GLFW must not include a GL header of its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <cstdlib>
#include <vector>

#include "core/error.hpp"

namespace glintlab {

namespace {

std::string& last_glfw_error() {
  static std::string error;
  return error;
}

void on_glfw_error(int code, const char* description) {
  last_glfw_error() = std::string(description ? description : "") + " (GLFW error " + std::to_string(code) + ")";
}

constexpr const char* kDisplayHint =
    "glintlab view needs a display: run it on a desktop, or headless under a virtual one "
    "(Debian package xvfb: xvfb-run -a -s '-screen 0 1600x1000x24' glintlab view ...)";

}  // namespace

ViewWindow::ViewWindow(int width, int height, const std::string& title) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) throw RuntimeFailure("cannot start GLFW: " + last_glfw_error() + ". " + kDisplayHint);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw RuntimeFailure("cannot open an OpenGL 4.5 core window: " + last_glfw_error() +
                         ". glintlab needs OpenGL 4.5 (Debian: libgl1-mesa-dri for llvmpipe, or the NVIDIA driver)");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  imgui_context_ = true;
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written beside wherever it was started
  ImGui::StyleColorsDark();
  imgui_glfw_ = ImGui_ImplGlfw_InitForOpenGL(window_, true);
  imgui_opengl_ = imgui_glfw_ && ImGui_ImplOpenGL3_Init("#version 450");
  if (!imgui_opengl_) {
    close();
    throw RuntimeFailure("cannot start Dear ImGui's GLFW/OpenGL 3 backends in the window");
  }
}

ViewWindow::~ViewWindow() { close(); }

void ViewWindow::close() {
  if (imgui_opengl_) ImGui_ImplOpenGL3_Shutdown();
  if (imgui_glfw_) ImGui_ImplGlfw_Shutdown();
  if (imgui_context_) ImGui::DestroyContext();
  imgui_opengl_ = imgui_glfw_ = imgui_context_ = false;
  if (window_) {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  window_ = nullptr;
}

std::string ViewWindow::platform() const { return std::string("GLFW window (") + glfwGetVersionString() + ")"; }

bool ViewWindow::should_close() const { return glfwWindowShouldClose(window_); }

void ViewWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void ViewWindow::begin_frame() {
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ViewWindow::render_ui() {
  ImGui::Render();
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, w, h);
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void ViewWindow::present() { glfwSwapBuffers(window_); }

Image ViewWindow::read_window() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  std::vector<unsigned char> rgba(static_cast<std::size_t>(w) * h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  Image out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = &rgba[(static_cast<std::size_t>(h - 1 - y) * w + x) * 4];
      out.at(x, y) = glm::vec3(p[0], p[1], p[2]) / 255.0f;
    }
  return out;
}

}  // namespace glintlab
