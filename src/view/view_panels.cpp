#include "view/view_panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <glm/geometric.hpp>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/error.hpp"
#include "view/view_script.hpp"
#include "shading/registry.hpp"
#include "view/camera_controls.hpp"

namespace glintlab {

namespace {

constexpr float kPanelWidth = 360.0f;
constexpr float kMagnifierSide = 256.0f;  // screen pixels
constexpr double kPlaybackFps = 24.0;     // the MP4s' rate

ImTextureID texture_id(GLuint texture) { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture)); }

std::string time_text(const GpuTime& t, bool software) {
  char text[96];
  // On llvmpipe the timer query misses the rasterisation (gl/gpu_timer.hpp): the wall time is the measure.
  // On llvmpipe the timer query may miss rasterisation done at the read or finish (gl/gpu_timer.hpp):
  // the wall time is the measure there.
  if (software) std::snprintf(text, sizeof text, "%.1f ms wall (software; GPU timer %.1f ms)", t.wall_ms, t.gpu_ms);
  else std::snprintf(text, sizeof text, "%.2f ms GPU timer, %.1f ms wall", t.gpu_ms, t.wall_ms);
  return text;
}

}  // namespace

void ViewPanels::draw(Viewer& viewer) {
  try {
    keyboard_input(viewer);
    camera_input(viewer);
    if (viewer.state().playing && ImGui::GetTime() - last_play_step_ >= 1.0 / kPlaybackFps) {
      last_play_step_ = ImGui::GetTime();
      viewer.step_frame(1);
    }
    side_panel(viewer);
  } catch (const InputError& e) {
    message_ = e.what();
  }
  picture(viewer);
}

void ViewPanels::side_panel(Viewer& viewer) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y), ImGuiCond_Always);
  ImGui::Begin("glintlab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  Session& session = viewer.session();
  const ViewState& s = viewer.state();
  ImGui::TextWrapped("%s, %dx%d, %s", session.scene().source.c_str(), viewer.width(), viewer.height(),
                     session.context().info().renderer.c_str());

  if (ImGui::CollapsingHeader("Method", ImGuiTreeNodeFlags_DefaultOpen)) method_controls(viewer, false);

  if (ImGui::CollapsingHeader("Compare", ImGuiTreeNodeFlags_DefaultOpen)) {
    int mode = static_cast<int>(s.mode);
    ImGui::RadioButton("single", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("split", &mode, 1);
    ImGui::SameLine();
    ImGui::RadioButton("A/B flip (F)", &mode, 2);
    if (mode != static_cast<int>(s.mode)) viewer.set_mode(static_cast<CompareMode>(mode));
    const std::string second = s.second == SecondImage::Reference ? "reference" : s.b.method->id;
    if (ImGui::BeginCombo("with", second.c_str())) {
      if (ImGui::Selectable("reference", s.second == SecondImage::Reference)) viewer.compare_with_reference();
      for (const auto& m : all_methods())
        if (ImGui::Selectable(m.id.c_str(), s.second == SecondImage::Method && s.b.method->id == m.id))
          viewer.select_method(true, m.id);
      ImGui::EndCombo();
    }
    if (s.mode == CompareMode::Split) {
      float split = s.split;
      if (ImGui::SliderFloat("split", &split, 0.0f, 1.0f, "%.2f")) viewer.set_split(split);
    }
    if (s.mode == CompareMode::Flip && ImGui::Button(s.showing_second ? "showing B: flip" : "showing A: flip"))
      viewer.flip();
    bool overlay = s.error_overlay;
    float opacity = s.overlay_opacity;
    if (ImGui::Checkbox("error map (E)", &overlay)) viewer.set_error_overlay(overlay, opacity);
    if (s.error_overlay && ImGui::SliderFloat("opacity", &opacity, 0.0f, 1.0f, "%.2f")) viewer.set_error_overlay(true, opacity);
    if (s.mode != CompareMode::Single && s.second == SecondImage::Method && ImGui::TreeNode("second method's parameters")) {
      method_controls(viewer, true);
      ImGui::TreePop();
    }
    if (const ReferenceFrame* r = viewer.reference())
      ImGui::TextWrapped("reference: %d spp, noise RMSE %.3g", r->spp, r->noise_rmse());
    else if (viewer.reference_pending())
      ImGui::TextWrapped("reference: rendering %d spp, or reading it from the cache...", session.reference_settings().spp);
  }

  if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) camera_controls(viewer);

  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
    float exposure = s.exposure, bloom = s.bloom;
    if (ImGui::SliderFloat("exposure", &exposure, -10.0f, 10.0f, "%.2f stops")) viewer.set_exposure(exposure);
    if (ImGui::SliderFloat("bloom", &bloom, 0.0f, 1.0f, "%.3f")) viewer.set_bloom(bloom);
    if (ImGui::Button("the scene's")) {
      viewer.set_exposure(session.scene().film.exposure);
      viewer.set_bloom(session.scene().film.bloom);
    }
    ImGui::Checkbox("magnifier (M)", &magnifier_);
    ImGui::SameLine();
    ImGui::SliderInt("zoom", &magnifier_zoom_, kMinMagnifierZoom, kMaxMagnifierZoom);
  }

  if (ImGui::CollapsingHeader("Frame time", ImGuiTreeNodeFlags_DefaultOpen)) {
    const bool software = session.context().is_software();
    if (const TimedFrame* a = viewer.shown(false)) ImGui::TextWrapped("A %s: %s", s.a.method->id.c_str(), time_text(a->time, software).c_str());
    if (const TimedFrame* b = viewer.shown(true); b && s.mode != CompareMode::Single && s.second == SecondImage::Method)
      ImGui::TextWrapped("B %s: %s", s.b.method->id.c_str(), time_text(b->time, software).c_str());
    bool continuous = s.continuous;
    if (ImGui::Checkbox("re-render every frame", &continuous)) viewer.set_continuous(continuous);
  }

  if (ImGui::CollapsingHeader("Screenshot", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::InputText("path", &screenshot_path_);
    if (ImGui::Button("save EXR + PNG (P)")) message_ = "written " + viewer.screenshot(screenshot_path_) + " and .png";
  }
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
  ImGui::End();
}

void ViewPanels::method_controls(Viewer& viewer, bool second_slot) {
  const MethodSlot& slot = second_slot ? viewer.state().b : viewer.state().a;
  ImGui::PushID(second_slot ? "B" : "A");
  if (ImGui::BeginCombo("method", slot.method->id.c_str())) {
    for (const auto& m : all_methods())
      if (ImGui::Selectable(m.id.c_str(), m.id == slot.method->id)) viewer.select_method(second_slot, m.id);
    ImGui::EndCombo();
  }
  ImGui::TextWrapped("%s", slot.method->title.c_str());
  // One control per declared parameter: what the descriptor says is all the UI knows.
  for (const ParamDecl& p : slot.method->params) {
    // Host-only and compile-time parameters apply when the slider is let go: each value is a
    // precompute or a program. The others apply while dragging.
    const bool deferred = p.host_only || p.compile_time;
    const std::string key = (second_slot ? "B." : "A.") + p.name;
    const auto editing = editing_.find(key);
    float value = deferred && editing != editing_.end() ? editing->second : slot.params.at(p.name);
    const char* note = p.host_only ? " [precompute]" : p.compile_time ? " [compile]" : "";
    const std::string label = p.name + note;
    if (!p.choices.empty()) {
      const auto current = static_cast<std::size_t>(value);
      if (ImGui::BeginCombo(label.c_str(), p.choices.at(current).c_str())) {
        for (std::size_t i = 0; i < p.choices.size(); ++i)
          if (ImGui::Selectable(p.choices[i].c_str(), i == current)) viewer.set_param(second_slot, p.name, p.choices[i]);
        ImGui::EndCombo();
      }
    } else {
      const bool whole = p.default_value == std::floor(p.default_value) && p.min == std::floor(p.min) &&
                         p.max == std::floor(p.max) && deferred;
      bool changed = false;
      if (whole) {
        int v = static_cast<int>(value);
        changed = ImGui::SliderInt(label.c_str(), &v, static_cast<int>(p.min), static_cast<int>(p.max));
        value = static_cast<float>(v);
      } else {
        changed = ImGui::SliderFloat(label.c_str(), &value, p.min, p.max, "%.4g");
      }
      if (!deferred && changed) viewer.set_param_value(second_slot, p.name, value);
      if (deferred && changed) editing_[key] = value;
      if (deferred && ImGui::IsItemDeactivatedAfterEdit()) {
        editing_.erase(key);
        viewer.set_param_value(second_slot, p.name, value);
      }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%s; default %s)", p.description.c_str(), p.allowed().c_str(), p.default_text().c_str());
  }
  if (ImGui::Button("defaults")) viewer.reset_params(second_slot);
  ImGui::PopID();
}

void ViewPanels::camera_controls(Viewer& viewer) {
  const ViewState& s = viewer.state();
  if (s.free_camera) {
    ImGui::TextWrapped("free camera (left drag: orbit, wheel: dolly, right drag: look, W/A/S/D/R/Q: fly)");
    if (ImGui::Button("back to the path")) viewer.return_to_path();
  } else {
    int frame = s.frame;
    if (ImGui::SliderInt("frame", &frame, 0, viewer.frames() - 1)) viewer.set_frame(frame);
    if (ImGui::Button("<")) viewer.step_frame(-1);
    ImGui::SameLine();
    if (ImGui::Button(s.playing ? "pause (space)" : "play (space)")) viewer.set_playing(!s.playing);
    ImGui::SameLine();
    if (ImGui::Button(">")) viewer.step_frame(1);
    ImGui::TextWrapped("the scene's path; drag the picture to leave it");
  }
}

void ViewPanels::picture(Viewer& viewer) {
  const ImGuiIO& io = ImGui::GetIO();
  const float avail_w = std::max(1.0f, io.DisplaySize.x - kPanelWidth), avail_h = std::max(1.0f, io.DisplaySize.y);
  const float fit = std::min(avail_w / static_cast<float>(viewer.width()), avail_h / static_cast<float>(viewer.height()));
  // Whole multiples when enlarging, so every film pixel covers the same number of screen pixels.
  image_scale_ = fit >= 1.0f ? std::floor(fit) : fit;
  const float w = image_scale_ * static_cast<float>(viewer.width()), h = image_scale_ * static_cast<float>(viewer.height());
  image_x_ = kPanelWidth + std::floor((avail_w - w) / 2);
  image_y_ = std::floor((avail_h - h) / 2);
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->AddImage(texture_id(viewer.texture()), ImVec2(image_x_, image_y_), ImVec2(image_x_ + w, image_y_ + h));
  const ViewState& s = viewer.state();
  if (s.mode == CompareMode::Split) {
    const float x = image_x_ + std::round(s.split * static_cast<float>(viewer.width())) * image_scale_;
    draw->AddLine(ImVec2(x, image_y_), ImVec2(x, image_y_ + h), IM_COL32(255, 255, 255, 160));
  }
  const std::string second = s.second == SecondImage::Reference ? "reference" : s.b.method->id;
  const std::string label = s.mode == CompareMode::Single ? s.a.method->id
                            : s.mode == CompareMode::Split ? s.a.method->id + " | " + second
                                                           : (s.showing_second ? "B: " + second : "A: " + s.a.method->id);
  draw->AddText(ImVec2(image_x_ + 6, image_y_ + 4), IM_COL32(255, 255, 255, 230), label.c_str());

  if (pinned_) {
    magnifier(viewer, static_cast<float>(pinned_->x) + 0.5f, static_cast<float>(pinned_->y) + 0.5f);
  } else if (magnifier_ && !io.WantCaptureMouse) {
    const float fx = (io.MousePos.x - image_x_) / image_scale_, fy = (io.MousePos.y - image_y_) / image_scale_;
    if (fx >= 0 && fy >= 0 && fx < static_cast<float>(viewer.width()) && fy < static_cast<float>(viewer.height()))
      magnifier(viewer, fx, fy);
  }
}

void ViewPanels::magnifier(Viewer& viewer, float film_x, float film_y) {
  const int zoom = pinned_ ? std::max(kMinMagnifierZoom, pinned_->z) : magnifier_zoom_;
  const float half = kMagnifierSide / static_cast<float>(zoom) / 2.0f;  // film pixels
  // Where it looks, outlined on the picture.
  ImGui::GetBackgroundDrawList()->AddRect(
      ImVec2(image_x_ + (film_x - half) * image_scale_, image_y_ + (film_y - half) * image_scale_),
      ImVec2(image_x_ + (film_x + half) * image_scale_, image_y_ + (film_y + half) * image_scale_),
      IM_COL32(255, 210, 60, 200));
  const float w = static_cast<float>(viewer.width()), h = static_cast<float>(viewer.height());
  const ImVec2 uv0((film_x - half) / w, (film_y - half) / h), uv1((film_x + half) / w, (film_y + half) / h);
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kMagnifierSide - 24, 8), ImGuiCond_Always);
  ImGui::Begin("magnifier", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
  ImGui::Image(texture_id(viewer.texture()), ImVec2(kMagnifierSide, kMagnifierSide), uv0, uv1);
  const int px = static_cast<int>(film_x), py = static_cast<int>(film_y);
  ImGui::Text("pixel (%d, %d), %dx", px, py, zoom);
  // The linear radiance under the cursor: what the metrics compare.
  auto value = [&](const Image& image) { return image.at(std::clamp(px, 0, image.width() - 1), std::clamp(py, 0, image.height() - 1)); };
  if (const TimedFrame* a = viewer.shown(false)) {
    const glm::vec3 v = value(a->frame.total);
    ImGui::Text("A   %.4g %.4g %.4g", v.r, v.g, v.b);
  }
  if (const ReferenceFrame* r = viewer.reference()) {
    const glm::vec3 v = value(r->mean.total);
    ImGui::Text("ref %.4g %.4g %.4g", v.r, v.g, v.b);
  }
  ImGui::End();
}

void ViewPanels::camera_input(Viewer& viewer) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return;
  constexpr float kDegreesPerPixel = 0.3f;
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left) && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0))
    viewer.move_camera(orbit_camera(viewer.camera(), -io.MouseDelta.x * kDegreesPerPixel, io.MouseDelta.y * kDegreesPerPixel));
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0))
    viewer.move_camera(look_camera(viewer.camera(), -io.MouseDelta.x * kDegreesPerPixel, -io.MouseDelta.y * kDegreesPerPixel));
  if (io.MouseWheel != 0) viewer.move_camera(dolly_camera(viewer.camera(), std::pow(0.9f, io.MouseWheel)));
}

void ViewPanels::keyboard_input(Viewer& viewer) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) viewer.flip();
  if (ImGui::IsKeyPressed(GLFW_KEY_E, false)) viewer.set_error_overlay(!viewer.state().error_overlay, viewer.state().overlay_opacity);
  if (ImGui::IsKeyPressed(GLFW_KEY_M, false)) magnifier_ = !magnifier_;
  if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) viewer.set_playing(!viewer.state().playing);
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) viewer.step_frame(1);
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) viewer.step_frame(-1);
  if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) message_ = "written " + viewer.screenshot(screenshot_path_) + " and .png";
  // Fly: the distance to the target per second, so a scene of any scale moves alike.
  const Camera c = viewer.camera();
  const float speed = glm::length(c.target - c.position) * io.DeltaTime;
  glm::vec3 move(0.0f);
  if (ImGui::IsKeyDown(GLFW_KEY_W)) move.z += speed;
  if (ImGui::IsKeyDown(GLFW_KEY_S)) move.z -= speed;
  if (ImGui::IsKeyDown(GLFW_KEY_D)) move.x += speed;
  if (ImGui::IsKeyDown(GLFW_KEY_A)) move.x -= speed;
  if (ImGui::IsKeyDown(GLFW_KEY_R)) move.y += speed;
  if (ImGui::IsKeyDown(GLFW_KEY_Q)) move.y -= speed;
  if (move != glm::vec3(0.0f)) viewer.move_camera(fly_camera(c, move));
}

}  // namespace glintlab
